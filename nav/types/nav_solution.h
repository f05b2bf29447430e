#pragma once
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

namespace deepnav {

// Stage of the paper's two-stage method.
enum class NavStage : std::uint8_t {
  kInit = 0,            // waiting for the first attitude and depth
  kWorkspace = 1,       // stage 1: panel not fixed, workspace map being built
  kOptimised = 2,       // stage 2: map ready, adaptive visual odometry
};

// Status bits: what the solution is good for.
enum NavStatusBits : std::uint32_t {
  kStatusAttitudeValid = 1u << 0,
  kStatusVelocityValid = 1u << 1,
  kStatusDepthValid = 1u << 2,
  kStatusPositionValid = 1u << 3,   // horizontal position aided (markers or VO) recently
  kStatusPanelFixed = 1u << 4,
  kStatusMapReady = 1u << 5,
  kStatusMagDisturbed = 1u << 6,    // compass de-weighted or refused: magnetic disturbance (nav/ekf/mag_disturbance.h)
};

// Per-source flags. Each source has a stale bit (timeout) and a rejected bit (last innovation gated).
enum NavSource : std::uint8_t { kSrcImu = 0, kSrcDvl, kSrcDepth, kSrcHeading, kSrcAttitude, kSrcMarkers,
                                kSrcVoOrb, kSrcVoPlanes, kSrcCamera, kSrcCount };
constexpr std::uint32_t staleBit(NavSource s) { return 1u << (2 * static_cast<unsigned>(s)); }
constexpr std::uint32_t rejectBit(NavSource s) { return 1u << (2 * static_cast<unsigned>(s) + 1); }

// The estimator's output at every loop tick (loop timing statistics live in LoopStats, not here, so that a
// replay reproduces this struct bit for bit whatever the machine's speed): pose of the robot in the odometry frame (ENU, REP-105), its velocity,
// covariances, stage and health.
struct NavSolution {
  TimeUs t_us = 0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_robot_in_odom_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_robot_radps = Eigen::Vector3d::Zero();  // bias-corrected angular rate, robot frame
  // Pose covariance, order [x y z roll pitch yaw] as in ROS (rotation errors about the odom axes).
  Eigen::Matrix<double, 6, 6> cov_pose = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix3d cov_v_mps2 = Eigen::Matrix3d::Zero();
  NavStage stage = NavStage::kInit;
  std::uint32_t status = 0;       // NavStatusBits
  std::uint32_t faults = 0;       // staleBit()/rejectBit() per NavSource
  double image_quality = -1.0;    // last image-quality score m_I in [0, 1], -1 when none yet
  std::uint32_t rejected_total = 0;
  std::uint32_t dropped_late_total = 0;
};

// True when every number in the solution is finite (the filter must never output anything else).
bool isFinite(const NavSolution& s);

}  // namespace deepnav
