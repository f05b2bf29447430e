#pragma once
#include <Eigen/Core>

#include "nav/ekf/filter_state.h"
#include "nav/ekf/imu_to_robot.h"
#include "nav/types/time.h"

namespace deepnav {

// Coarse alignment of a robot at (or near) rest: roll and pitch from the mean specific force (gravity
// seen from the robot, FLU: f = R^T (0, 0, g) = g (-sin pitch, sin roll cos pitch, cos roll cos pitch)),
// yaw from the compass, z from the depth sensor, x = y = 0 (the odometry origin), v = 0, biases 0.
class InitialAlignment {
 public:
  void clear() { *this = InitialAlignment(); }
  void addImu(const RobotImu& u, TimeUs t_us);
  void setYaw(double yaw_rad) { yaw_rad_ = yaw_rad; has_yaw_ = true; }
  void setDepth(double depth_m) { depth_m_ = depth_m; has_depth_ = true; }
  // imu_only: neither the compass's yaw nor the depth is waited for (EkfConfig::align_imu_only).
  bool ready(int imu_samples_required, bool imu_only = false) const;
  Eigen::Vector3d meanRate() const { return sum_w_ / static_cast<double>(count_); }

  // The aligned nominal state; p_depth_in_robot_m is the pressure port lever arm; gyro_bias_at_rest: the
  // mean rate is the gyro bias (EkfConfig::align_gyro_bias_at_rest).
  NominalState compute(const Eigen::Vector3d& p_depth_in_robot_m, bool gyro_bias_at_rest = false) const;

 private:
  Eigen::Vector3d sum_f_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d sum_w_ = Eigen::Vector3d::Zero();
  int count_ = 0;
  TimeUs last_imu_t_us_ = 0;
  double yaw_rad_ = 0.0;
  double depth_m_ = 0.0;
  bool has_yaw_ = false;
  bool has_depth_ = false;
};

// Rotation odom <- robot from ZYX Euler angles (yaw about z, then pitch about y, then roll about x).
Eigen::Quaterniond quatFromRollPitchYaw(double roll_rad, double pitch_rad, double yaw_rad);

}  // namespace deepnav
