#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav::sim {

// The exact state of the robot frame R (FLU) in the odometry frame O (ENU) at one instant, with the
// derivatives the sensor models need. Produced by Trajectory::stateAt().
struct KinematicState {
  double t_s = 0.0;
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_robot_in_odom_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d a_robot_in_odom_mps2 = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  Eigen::Vector3d w_robot_radps = Eigen::Vector3d::Zero();  // angular rate of R in R
  Eigen::Vector3d alpha_robot_radps2 = Eigen::Vector3d::Zero();  // d/dt w_robot_radps (IMU lever arm)
  Eigen::Vector3d f_robot_mps2 = Eigen::Vector3d::Zero();   // specific force in R: R^T (a - g_vec)
  double roll_rad = 0.0;   // ZYX Euler angles of q_odom_robot; yaw is continuous (not wrapped)
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;
};

}  // namespace deepnav::sim
