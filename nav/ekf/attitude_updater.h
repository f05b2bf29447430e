#pragma once
#include "nav/ekf/filter_state.h"
#include "nav/ekf/measurement_update.h"
#include "nav/types/attitude_sample.h"

namespace deepnav {

struct EkfConfig;

bool isValidAttitude(const AttitudeSample& m);

// Roll and pitch from an AHRS (ZYX Euler of R_odom_robot): roll = atan2(R21, R22), pitch = -asin(R20).
// With R = Exp(dtheta) R_hat, row 2 of dR is (dtheta_x R1j - dtheta_y R0j), so
//   H_roll  = [ R22 R11 - R21 R12,  R21 R02 - R22 R01, 0 ] / (R21^2 + R22^2)
//   H_pitch = [ -R10, R00, 0 ] / cos(pitch)
// (a rotation about odom z changes neither). Residuals wrapped; false near pitch +-90 deg.
bool linearizeAttitude(const FilterState& s, const AttitudeSample& m, const EkfConfig& config, Linearization* out);

}  // namespace deepnav
