#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/imu_sample.h"

namespace deepnav {

// IMU reading moved to the robot frame: the input of one propagation step (raw, biases not removed).
struct RobotImu {
  Eigen::Vector3d w_robot_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d f_robot_mps2 = Eigen::Vector3d::Zero();
};

// Rotates the sample into the robot frame and removes the lever-arm terms of a rigid body,
//   f_robot = R_robot_imu f_imu - alpha x r - w x (w x r),   r = p_imu_in_robot,
// with alpha from the difference of successive raw rates (zero when dt_s <= 0). The raw rate is used
// (not the bias-corrected one) so that the propagation Jacobian does not depend on the lever arm; the
// error this makes is second order in the gyro bias.
RobotImu imuToRobot(const ImuSample& sample, const Eigen::Quaterniond& q_robot_imu,
                    const Eigen::Vector3d& p_imu_in_robot_m, const Eigen::Vector3d& w_robot_prev_radps,
                    double dt_s);

}  // namespace deepnav
