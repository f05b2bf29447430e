#pragma once
#include <array>
#include <cstdint>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tools/sim/camera_tick.h"
#include "tools/sim/kinematic_state.h"
#include "vision/calib/flat_port.h"

namespace deepnav::sim {

// Scenario key `camera`: the forward-looking stereo rig (pinhole, rectified pair).
struct CameraConfig {
  bool enabled = true;
  double rate_hz = 10.0;     // stereo pairs per second
  int width_px = 688;
  int height_px = 516;
  double fx_px = 700.0;
  double fy_px = 700.0;
  double cx_px = 343.5;
  double cy_px = 257.5;
  double baseline_m = 0.30;  // the right camera sits baseline_m along the left camera's +x (to the right)
  std::array<double, 3> p_cam_in_robot_m{0.6, 0.15, -0.2};  // left camera's optical centre, robot frame
  // Rotation of a forward-looking FLU "camera body" frame in the robot frame (R_robot_body); the optical
  // frame (z forward, x right, y down) is fixed to that body. Zero: optical axis along robot +x.
  std::array<double, 3> mount_rpy_deg{0.0, 0.0, 0.0};
  // camera.port: a flat port in front of each camera (render/flat_port.h); off, the renderer draws a
  // rectified pinhole pair. With it, fx..cy are the cameras' in-air intrinsics and the images are raw.
  bool flat_port = false;
  FlatPort port{};

  bool operator==(const CameraConfig&) const = default;
};

// Camera extrinsics and the true camera poses at a given robot state.
class CameraRig {
 public:
  bool init(const CameraConfig& config, std::string* error);
  CameraTick tick(const KinematicState& truth, TimeUs t_us, std::uint32_t frame_index) const;

  const Eigen::Matrix3d& R_robot_cam() const { return R_robot_cam_; }
  const Eigen::Vector3d& p_left_cam_in_robot_m() const { return p_left_cam_in_robot_m_; }
  Eigen::Vector3d p_right_cam_in_robot_m() const;

 private:
  CameraConfig config_;
  Eigen::Matrix3d R_robot_cam_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_left_cam_in_robot_m_ = Eigen::Vector3d::Zero();
};

}  // namespace deepnav::sim
