#pragma once
#include <Eigen/Core>

namespace deepnav {

// Layout of the error state (the filter estimates the error of the nominal state, not the state):
//   [ dp (3) | dv (3) | dtheta (3) | dbg (3) | dba (3) | clone 0: dp, dtheta (6) | clone 1 ... | systematic ]
// The systematic block (systematic_states.h: DVL scale factor and misalignment, compass bias and
// deviation) holds only the states the board switches on, in a fixed order, right after the clones in
// use; with none on the layout is the 15-state core plus clones, exactly as without the block.
// dtheta is a rotation error about the odometry axes (a left perturbation): R = Exp(dtheta) * R_hat,
// so the attitude covariance is directly the ROS [roll pitch yaw] block about fixed odom axes.
// The clone errors use the same convention. Sizes are compile-time so that nothing allocates after
// init(); the number of clones in use (and so the used block of P) is tracked at run time.
namespace es {
constexpr int kP = 0;
constexpr int kV = 3;
constexpr int kTheta = 6;
constexpr int kBg = 9;
constexpr int kBa = 12;
constexpr int kCoreDim = 15;
constexpr int kCloneDim = 6;       // [dp, dtheta] of one cloned pose
constexpr int kMaxClones = 4;      // compile-time cap; EkfConfig::max_clones chooses up to this
constexpr int kMaxSysDim = 12;     // DVL scale 1 + misalignment 3 + velocity bias 3 + compass bias 1 + deviation 4
constexpr int kMaxDim = kCoreDim + kCloneDim * kMaxClones + kMaxSysDim;
constexpr int kMaxMeasDim = 6;     // largest measurement (6-DoF pose)

constexpr int cloneOffset(int slot) { return kCoreDim + kCloneDim * slot; }
}  // namespace es

// Matrices with a compile-time maximum and a run-time size: Eigen keeps them inline (no heap).
using CovMatrix = Eigen::Matrix<double, es::kMaxDim, es::kMaxDim>;
using ErrorVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, es::kMaxDim, 1>;
using MeasVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, es::kMaxMeasDim, 1>;
using MeasMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, es::kMaxMeasDim, es::kMaxMeasDim>;
using MeasJacobian = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, es::kMaxMeasDim, es::kMaxDim>;
using GainMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, es::kMaxDim, es::kMaxMeasDim>;
using CoreMatrix = Eigen::Matrix<double, es::kCoreDim, es::kCoreDim>;

}  // namespace deepnav
