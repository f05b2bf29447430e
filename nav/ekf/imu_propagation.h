#pragma once
#include <Eigen/Core>

#include "nav/ekf/error_state.h"
#include "nav/ekf/filter_state.h"
#include "nav/ekf/imu_to_robot.h"

namespace deepnav {

struct EkfConfig;

// One propagation step of the nominal state over dt_s, the IMU input held constant over the step (the
// sample stamped at the end of an interval describes that interval, as IMU delta outputs do):
//   theta = (w - bg) dt,  R+ = R Exp(theta),  Rm = R Exp(theta / 2)               (mid-step attitude)
//   a = Rm (f - ba) + g,  g = (0, 0, -gravity)
//   p+ = p + v dt + a dt^2 / 2,  v+ = v + a dt,  bg+ = bg,  ba+ = ba
NominalState propagateNominal(const NominalState& x, const RobotImu& u, double dt_s, double gravity_mps2);

// Phi = d(error after step) / d(error before step) of propagateNominal, with R = Exp(dtheta) R_hat:
//   d a / d dtheta = -[Rm (f - ba)]x,  d a / d dba = -Rm,  d a / d dbg = Rm [f - ba]x Jr(theta/2) dt/2
//   d theta+ / d dbg = -R+ Jr(theta) dt                           (Sola 2018, eqs. 143 and 69)
CoreMatrix propagationJacobian(const NominalState& x, const RobotImu& u, double dt_s);

// Discrete process noise of the step: white noise densities held over the step (the IMU sample is an
// average over its interval), so dv ~ sigma_a^2 dt, dp ~ sigma_a^2 dt^3 / 4, dp dv ~ sigma_a^2 dt^2 / 2,
// dtheta ~ sigma_g^2 dt, and the biases random-walk with sigma_b^2 dt.
CoreMatrix propagationNoise(const EkfConfig& config, double dt_s);

// P_core = Phi P_core Phi^T + Q, and the core-to-clone cross blocks become Phi P_core,clone (the clones
// do not move).
void propagateCovariance(const CoreMatrix& Phi, const CoreMatrix& Q, FilterState* s);

}  // namespace deepnav
