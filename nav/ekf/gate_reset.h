#pragma once
#include "nav/ekf/filter_state.h"
#include "nav/types/nav_solution.h"

namespace deepnav {

struct EkfConfig;

// Recovery from a gate lockout of one aiding source (EkfConfig::gate_reset_after_us): the error states the
// source observes are decorrelated from the rest (their rows and columns of P zeroed, which keeps P
// positive semi-definite) and their variances raised to at least the initial ones:
//   DVL:      velocity and accelerometer bias
//   depth:    z position and z velocity
//   compass:  yaw and gyro bias
//   AHRS:     roll and pitch
//   markers:  position and attitude (a marker pose observes both; the lockout seen at sea: an occlusion of
//             the markers, plane VO results pulling the position 10 cm off meanwhile, every marker pose
//             refused afterwards for the rest of the dive)
// The next sample of the source then meets a gate sized by those variances: a source that is merely
// ahead of an overconfident filter gets back in; random values over a sensor's range still fall outside
// it (e.g. 3 sigma = 0.3 m/s against DVL garbage of +-5 m/s). Other sources (the VO): nothing.
void resetObservedStates(NavSource source, const EkfConfig& config, FilterState* s);

}  // namespace deepnav
