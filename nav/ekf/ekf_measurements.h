#pragma once
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/nav_solution.h"
#include "nav/types/time.h"

namespace deepnav {

// Measured pose of the robot in the odometry frame, e.g. from a marker whose pose in odom is known.
struct PoseMeasurement {
  TimeUs t_us = 0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  // Order [x y z roll pitch yaw] (ROS); the rotation error is about the odom axes: q_meas = Exp(n) q_true.
  Eigen::Matrix<double, 6, 6> cov_pose = Eigen::Matrix<double, 6, 6>::Identity();
  NavSource source = kSrcMarkers;  // which health slot counts it
};

// Visual odometry between two image times a < b: pose of the robot at b in the robot frame at a.
// The state at a lives in the clone `clone_id` (Ekf::clonePose at a); the measurement is fused at t_us = b.
struct RelativePoseMeasurement {
  TimeUs t_us = 0;                 // capture time of the later image (b)
  std::uint32_t clone_id = 0;      // clone taken at the earlier image (a)
  Eigen::Quaterniond q_robota_robotb = Eigen::Quaterniond::Identity();  // R_a^T R_b
  Eigen::Vector3d p_robotb_in_robota_m = Eigen::Vector3d::Zero();      // R_a^T (p_b - p_a)
  bool has_translation = true;     // false: rotation only (e.g. scale unknown)
  // Order [x y z roll pitch yaw]: translation in frame a, rotation error about the robot axes at b,
  // q_meas = q_true Exp(n). Without translation only the lower-right 3x3 block is used.
  Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Identity();
  bool release_clone = false;      // marginalise the clone right after this update
  NavSource source = kSrcVoOrb;
};

}  // namespace deepnav
