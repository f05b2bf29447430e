#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/ekf/error_state.h"
#include "nav/types/time.h"

namespace deepnav {

// Systematic sensor errors, nominal values (systematic_states.h gives the models); zero when not estimated.
struct SystematicErrors {
  double dvl_scale = 0.0;  // v_measured = (1 + s) v_true (sound-speed error)
  // Residual DVL mounting rotation as a rotation vector: R_robot_dvl_true = R_robot_dvl Exp(alpha).
  Eigen::Vector3d dvl_misalignment_rad = Eigen::Vector3d::Zero();
  // Velocity bias of the bottom track in the DVL axes, m/s: v_measured = ... + b (the datasheet's "+-x cm/s"
  // term of the accuracy, e.g. beam-geometry and transducer errors).
  Eigen::Vector3d dvl_bias_mps = Eigen::Vector3d::Zero();
  double heading_bias_rad = 0.0;  // compass residual bias (with the deviation's constant term A)
  // Deviation terms [B, C, D, E] of B sin psi + C cos psi + D sin 2psi + E cos 2psi, psi magnetic heading.
  Eigen::Vector4d heading_deviation_rad = Eigen::Vector4d::Zero();
};

// Offsets of the estimated systematic states inside the systematic block (-1: not estimated), fixed at
// init from the config; dim is the block's size.
struct SystematicLayout {
  int dvl_scale = -1;
  int dvl_misalignment = -1;
  int dvl_bias = -1;
  int heading_bias = -1;
  int heading_deviation = -1;
  int dim = 0;
};

// Nominal (best-estimate) state of the robot in the odometry frame (ENU, REP-105). Biases are expressed
// in the robot frame (FLU), i.e. after the IMU mounting rotation.
struct NominalState {
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_robot_in_odom_mps = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  Eigen::Vector3d b_gyro_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d b_accel_mps2 = Eigen::Vector3d::Zero();
  SystematicErrors sys;
};

// A stochastic clone: the pose of the robot at an earlier time (an image capture), kept in the state so
// that a relative measurement between that time and a later one can be fused (Roumeliotis & Burdick,
// "Stochastic cloning", ICRA 2002).
struct PoseClone {
  std::uint32_t id = 0;
  TimeUs t_us = 0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
};

// Everything the filter needs to continue from a given time: what the state history snapshots.
struct FilterState {
  TimeUs t_us = 0;
  NominalState x;
  std::array<PoseClone, es::kMaxClones> clones{};
  int n_clones = 0;
  // Last IMU sample in the robot frame, raw (not bias corrected): the rate is needed by the DVL lever arm
  // and by the next step's angular acceleration.
  Eigen::Vector3d w_robot_meas_radps = Eigen::Vector3d::Zero();
  bool has_imu = false;
  SystematicLayout sys_layout;
  // Capture time of the last accepted absolute or relative pose (markers, VO); -1 none. The systematic
  // states are corrected only while this is recent (Ekf::considerUnaided).
  TimeUs last_pose_fused_t_us = -1;
  CovMatrix P = CovMatrix::Zero();  // only the top-left dim() x dim() block is meaningful

  int sysOffset() const { return es::kCoreDim + es::kCloneDim * n_clones; }
  // Index in the error state of a systematic state at layout offset rel; -1 when it is not estimated.
  int sysIndex(int rel) const { return rel < 0 ? -1 : sysOffset() + rel; }
  int dim() const { return sysOffset() + sys_layout.dim; }
};

// Copies src into dst, the covariance only over its used block (a full copy is 12 kB).
void copyFilterState(const FilterState& src, FilterState* dst);

// Applies an error-state correction to the nominal state (the retraction):
//   p += dp, v += dv, R = Exp(dtheta) R, bg += dbg, ba += dba, and likewise for each clone; the
// systematic states estimated add their corrections.
void injectErrorState(const ErrorVector& dx, FilterState* s);

// Same retraction for the core state only, as used by the Jacobian tests.
NominalState retractNominal(const NominalState& x, const Eigen::Matrix<double, es::kCoreDim, 1>& dx);

// True when every nominal number and the used covariance block are finite.
bool isFiniteState(const FilterState& s);

}  // namespace deepnav
