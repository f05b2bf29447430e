#include "tools/sim/sensors/camera_rig.h"

#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {
// Optical axes expressed in a forward-looking FLU body: x_opt = -y_body (right), y_opt = -z_body (down),
// z_opt = x_body (forward). Columns are the optical axes.
Eigen::Matrix3d bodyFromOptical() {
  Eigen::Matrix3d R;
  R << 0.0, 0.0, 1.0,
      -1.0, 0.0, 0.0,
       0.0, -1.0, 0.0;
  return R;
}
}  // namespace

bool CameraRig::init(const CameraConfig& config, std::string* error) {
  if (!(config.rate_hz > 0.0) || !(config.baseline_m > 0.0)) {
    if (error) *error = "camera: rate_hz and baseline_m must be > 0";
    return false;
  }
  config_ = config;
  R_robot_cam_ = rotationFromRpyDeg(config.mount_rpy_deg) * bodyFromOptical();
  p_left_cam_in_robot_m_ = toVector(config.p_cam_in_robot_m);
  return true;
}

Eigen::Vector3d CameraRig::p_right_cam_in_robot_m() const {
  return p_left_cam_in_robot_m_ + R_robot_cam_.col(0) * config_.baseline_m;
}

CameraTick CameraRig::tick(const KinematicState& truth, TimeUs t_us, std::uint32_t frame_index) const {
  CameraTick c;
  c.t_us = t_us;
  c.frame_index = frame_index;
  const Eigen::Quaterniond q_robot_cam(R_robot_cam_);
  c.q_odom_left_cam = (truth.q_odom_robot * q_robot_cam).normalized();
  c.q_odom_right_cam = c.q_odom_left_cam;
  c.p_left_cam_in_odom_m = truth.p_robot_in_odom_m + truth.q_odom_robot * p_left_cam_in_robot_m_;
  c.p_right_cam_in_odom_m = truth.p_robot_in_odom_m + truth.q_odom_robot * p_right_cam_in_robot_m();
  return c;
}

}  // namespace deepnav::sim
