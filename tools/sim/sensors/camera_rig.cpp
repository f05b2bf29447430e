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

void applyCameraPreset(CameraPreset preset, CameraConfig* c) {
  if (preset != CameraPreset::kDexrov) return;
  c->width_px = 688;
  c->height_px = 516;
  c->fx_px = 580.0;
  c->fy_px = 580.0;
  c->cx_px = 344.0;
  c->cy_px = 258.0;
  c->baseline_m = 0.30;
  c->flat_port = true;
  c->port = FlatPort{};
  c->port.pinhole_to_glass_m = 0.0028;
  c->port.glass_thickness_m = 0.020;
  c->port.n_glass = 1.7751;
}

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
  c.exposure_t_us = t_us;  // the stamp may be shifted later (SensorSimulator, timing.camera); this is not
  c.frame_index = frame_index;
  const Eigen::Quaterniond q_robot_cam(R_robot_cam_);
  c.q_odom_left_cam = (truth.q_odom_robot * q_robot_cam).normalized();
  c.q_odom_right_cam = c.q_odom_left_cam;
  c.p_left_cam_in_odom_m = truth.p_robot_in_odom_m + truth.q_odom_robot * p_left_cam_in_robot_m_;
  c.p_right_cam_in_odom_m = truth.p_robot_in_odom_m + truth.q_odom_robot * p_right_cam_in_robot_m();
  // A point fixed to the robot moves at v + w x p (w in R); both expressed in the optical frame.
  const Eigen::Matrix3d R_cam_robot = R_robot_cam_.transpose();
  const Eigen::Vector3d v_robot_in_robot = truth.q_odom_robot.conjugate() * truth.v_robot_in_odom_mps;
  c.w_cam_radps = R_cam_robot * truth.w_robot_radps;
  c.v_left_cam_mps = R_cam_robot * (v_robot_in_robot + truth.w_robot_radps.cross(p_left_cam_in_robot_m_));
  c.v_right_cam_mps = R_cam_robot * (v_robot_in_robot + truth.w_robot_radps.cross(p_right_cam_in_robot_m()));
  return c;
}

}  // namespace deepnav::sim
