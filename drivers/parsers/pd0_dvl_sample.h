#pragma once
#include "drivers/parsers/pd0_ensemble.h"
#include "nav/types/dvl_sample.h"

namespace deepnav {

// Bottom-track velocity of an ensemble as a DvlSample in the DVL's FLU frame.
//
// PD0 stores the velocity of the bottom relative to the instrument, in the frame chosen by EX
// (fixed leader byte 25): beam, instrument, ship or earth. For a down-looking Janus head the RDI
// instrument frame is X starboard (beam 1 -> beam 2), Y forward (towards beam 3), Z up, so
// FLU = (Y, -X, Z) and the DVL's own velocity is minus the bottom's. Beam velocities are combined
// with the standard Janus matrix (RDI "ADCP Coordinate Transformation", eq. for a convex head);
// earth velocities are rotated back with the ensemble's heading, pitch and roll (RDI eq. 18-19,
// internal tilt sensor without gimbal correction). Returns false when the ensemble has no bottom
// track, no fixed leader, or is up-facing; the sample is then untouched.
bool pd0ToDvlSample(const Pd0Ensemble& ensemble, TimeUs t_us, DvlSample* sample);

}  // namespace deepnav
