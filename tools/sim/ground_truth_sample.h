#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

namespace deepnav {

// True state of the robot (FLU) in the odometry frame (ENU), at IMU rate, for scoring the estimator.
struct GroundTruthSample {
  TimeUs t_us = 0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_robot_in_odom_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_robot_radps = Eigen::Vector3d::Zero();  // angular rate of the robot, robot frame
  // The simulated IMU's biases at this time (IMU frame), to score bias estimates. Zero when the IMU is off.
  Eigen::Vector3d gyro_bias_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_mps2 = Eigen::Vector3d::Zero();
};

}  // namespace deepnav
