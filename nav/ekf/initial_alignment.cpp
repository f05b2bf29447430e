#include "nav/ekf/initial_alignment.h"

#include <cmath>

namespace deepnav {

void InitialAlignment::addImu(const RobotImu& u, TimeUs t_us) {
  sum_f_ += u.f_robot_mps2;
  sum_w_ += u.w_robot_radps;
  ++count_;
  last_imu_t_us_ = t_us;
}

bool InitialAlignment::ready(int imu_samples_required, bool imu_only) const {
  return count_ >= imu_samples_required && ((has_yaw_ && has_depth_) || imu_only);
}

Eigen::Quaterniond quatFromRollPitchYaw(double roll_rad, double pitch_rad, double yaw_rad) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitX()));
}

NominalState InitialAlignment::compute(const Eigen::Vector3d& p_depth_in_robot_m, bool gyro_bias_at_rest) const {
  const Eigen::Vector3d f = sum_f_ / static_cast<double>(count_);
  const double roll = std::atan2(f.y(), f.z());
  const double pitch = std::atan2(-f.x(), std::hypot(f.y(), f.z()));
  NominalState x;
  x.q_odom_robot = quatFromRollPitchYaw(roll, pitch, yaw_rad_);
  const Eigen::Vector3d port_offset = x.q_odom_robot * p_depth_in_robot_m;
  x.p_robot_in_odom_m = Eigen::Vector3d(0.0, 0.0, -depth_m_ - port_offset.z());
  if (gyro_bias_at_rest) x.b_gyro_radps = meanRate();
  return x;
}

}  // namespace deepnav
