#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav {

// One pose of a trajectory, as in a TUM file: time in seconds, pose of the robot in the odometry frame.
struct StampedPose {
  double t_s = 0.0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
};

}  // namespace deepnav
