#pragma once
#include "nav/ekf/ekf_measurements.h"
#include "nav/ekf/filter_state.h"
#include "nav/ekf/measurement_update.h"

namespace deepnav {

// Finite, unit-norm quaternion, and a covariance that is finite, symmetric and positive definite.
bool isValidPose(const PoseMeasurement& m);

// Absolute pose T_odom_robot. Residual [p_m - p ; Log(R_m R^T)]. With R = Exp(dtheta) R_hat,
//   Log(R_m R_hat^T Exp(-dtheta)) ~= r0 - Jr^-1(r0) dtheta      (Sola 2018 eq. 146)
// so H = [ I 0 0 0 0 ; 0 0 Jr^-1(r0) 0 0 ] over (dp dv dtheta dbg dba); R = cov_pose.
bool linearizePose(const FilterState& s, const PoseMeasurement& m, Linearization* out);

}  // namespace deepnav
