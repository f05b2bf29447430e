#include "nav/ekf/imu_to_robot.h"

namespace deepnav {

RobotImu imuToRobot(const ImuSample& sample, const Eigen::Quaterniond& q_robot_imu,
                    const Eigen::Vector3d& p_imu_in_robot_m, const Eigen::Vector3d& w_robot_prev_radps,
                    double dt_s) {
  RobotImu out;
  out.w_robot_radps = q_robot_imu * sample.w_imu_radps;
  out.f_robot_mps2 = q_robot_imu * sample.f_imu_mps2;
  if (p_imu_in_robot_m.isZero(0.0)) return out;
  const Eigen::Vector3d& w = out.w_robot_radps;
  const Eigen::Vector3d& r = p_imu_in_robot_m;
  const Eigen::Vector3d alpha = dt_s > 0.0 ? ((w - w_robot_prev_radps) / dt_s).eval() : Eigen::Vector3d::Zero();
  out.f_robot_mps2 -= alpha.cross(r) + w.cross(w.cross(r));
  return out;
}

}  // namespace deepnav
