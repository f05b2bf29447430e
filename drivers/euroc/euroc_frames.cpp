#include "drivers/euroc/euroc_frames.h"

namespace deepnav {

Eigen::Matrix3d eurocRobotFromBody() {
  Eigen::Matrix3d R;
  R << 0, 0, 1,  //
      0, -1, 0,  //
      1, 0, 0;
  return R;
}

TimeUs eurocTimeUs(std::int64_t t_ns, std::int64_t t0_ns) {
  const std::int64_t d = t_ns - t0_ns;
  return static_cast<TimeUs>(d >= 0 ? (d + 500) / 1000 : -((-d + 500) / 1000));
}

ImuSample eurocImuSample(const EurocImuRow& row, const Eigen::Matrix3d& R_body_sensor, std::int64_t t0_ns) {
  const Eigen::Matrix3d R_robot_sensor = eurocRobotFromBody() * R_body_sensor;
  ImuSample s;
  s.t_us = eurocTimeUs(row.t_ns, t0_ns);
  s.w_imu_radps = R_robot_sensor * row.w_sensor_radps;
  s.f_imu_mps2 = R_robot_sensor * row.f_sensor_mps2;
  return s;
}

TruthSample eurocTruthSample(const EurocTruthRow& row, std::int64_t t0_ns) {
  TruthSample t;
  t.t_us = eurocTimeUs(row.t_ns, t0_ns);
  t.p_robot_in_odom_m = row.p_body_in_world_m;
  t.q_odom_robot = Eigen::Quaterniond(row.q_world_body.toRotationMatrix() * eurocRobotFromBody().transpose());
  t.q_odom_robot.normalize();
  t.v_robot_in_odom_mps = row.v_body_in_world_mps;
  return t;
}

}  // namespace deepnav
