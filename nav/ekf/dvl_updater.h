#pragma once
#include "nav/ekf/filter_state.h"
#include "nav/ekf/measurement_update.h"
#include "nav/types/dvl_sample.h"

namespace deepnav {

struct EkfConfig;

// True when the sample is usable: valid bottom lock, finite numbers, no negative variance.
bool isValidDvl(const DvlSample& m);

// Bottom-track velocity in the DVL frame (R_dr = R_robot_dvl^T, r = p_dvl_in_robot):
//   h(x) = R_dr (R^T v + (w - bg) x r)       (rigid body: velocity of the DVL point, robot axes)
//   H_v = R_dr R^T,  H_theta = R_dr R^T [v]x,  H_bg = R_dr [r]x
// w is the last raw robot-frame gyro rate held in the state. With the DVL scale factor s and misalignment
// alpha estimated (systematic_states.h): h(x) = (1 + s) Exp(-alpha) R_dr (R^T v + (w - bg) x r). Noise: the sample covariance when given,
// else FOM^2 I, else the configured sigma.
bool linearizeDvl(const FilterState& s, const DvlSample& m, const EkfConfig& config, Linearization* out);

}  // namespace deepnav
