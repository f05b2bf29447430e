#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

namespace deepnav {

// One IMU sample, expressed in the IMU frame (FLU, REP-103). The IMU frame is related to the robot
// frame by the board's mounting rotation and lever arm.
struct ImuSample {
  TimeUs t_us = 0;
  Eigen::Vector3d w_imu_radps = Eigen::Vector3d::Zero();  // angular rate of the IMU in its own frame
  Eigen::Vector3d f_imu_mps2 = Eigen::Vector3d::Zero();   // specific force (accelerometer output)
  // Optional orientation from an AHRS-type IMU: rotation IMU -> odometry frame (ENU).
  bool has_orientation = false;
  Eigen::Quaterniond q_odom_imu = Eigen::Quaterniond::Identity();
  double orientation_sigma_rad = 0.0;
};

}  // namespace deepnav
