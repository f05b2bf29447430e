#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

namespace deepnav {

// Ground truth of the robot (simulator only): pose of the robot frame R (FLU) in the odometry frame O
// (ENU), velocity in O and angular rate in R. Recorded on its own topic; the loop never consumes it.
struct TruthSample {
  TimeUs t_us = 0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  Eigen::Vector3d v_robot_in_odom_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_robot_radps = Eigen::Vector3d::Zero();
};

}  // namespace deepnav
