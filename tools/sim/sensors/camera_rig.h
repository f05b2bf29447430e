#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tools/sim/camera_tick.h"
#include "tools/sim/kinematic_state.h"
#include "vision/calib/flat_port.h"

namespace deepnav::sim {

// camera.noise_model: what the sensor noise follows (render/camera_sensor.h).
enum class SensorNoiseModel {
  kWaterPreset,  // the water preset's read and shot noise times the total gain (the default, as before)
  kEmva1288,     // camera.sensor's EMVA 1288 figures, shot and dark noise times the analogue gain the AE chose
};

// camera.sensor: the image sensor behind the auto exposure. The AE's total multiplier g (README: image
// formation) is split into an exposure time and an analogue gain, exposure first (less noise), then gain:
//   t = min(g exposure_ref, exposure_max),  a = g exposure_ref / t.
// Defaults: FLIR Blackfly S BFS-U3-04S2M (Sony IMX287, 720 x 540, 6.9 um, the 688 x 516 class), see
// tools/sim/README.md for the figures and their source.
struct CameraSensorConfig {
  double exposure_ref_ms = 4.0;    // exposure at which radiance 1 fills the well at 0 dB (lamp brightness)
  double exposure_max_ms = 20.0;   // longest exposure the AE uses before it raises the analogue gain
  double full_well_e = 22000.0;    // EMVA 1288 saturation capacity, electrons
  double dark_noise_e = 7.0;       // EMVA 1288 temporal dark noise, electrons rms

  bool operator==(const CameraSensorConfig&) const = default;
};

// One camera.arm window: the manipulator deploys from its stowed pose (under the vehicle, out of view)
// at t_start_s, holds its gripper reach_m ahead of and height_m above its base (moving slowly), and is
// stowed again by t_end_s (render/manipulator_arm.h).
struct ArmWindow {
  double t_start_s = 0.0;
  double t_end_s = 0.0;
  double reach_m = 0.6;      // gripper ahead of the arm base, robot x
  double height_m = 0.3;     // gripper above the arm base, robot z
  double lateral_m = 0.0;    // gripper to the left of the arm base, robot y
  double deploy_s = 4.0;     // unfolding (and folding) time inside the window
  double sway_m = 0.04;      // amplitude of the slow working motion of the gripper
  double sway_period_s = 12.0;

  bool operator==(const ArmWindow&) const = default;
};

// camera.preset: a named rig applied before the explicit keys (which override it).
enum class CameraPreset { kNone, kDexrov };
// kDexrov: the DexROV stereo rig (Luczynski, Pfingsthorn and Birk, "The Pinax-model for accurate and
// efficient refraction correction of underwater cameras in flat-pane housings", Ocean Engineering 133,
// 2017): 688 x 516, f 580 px, principal point (344, 258), 0.30 m baseline, behind flat ports of 20 mm
// glass (n 1.7751) with the pinhole 2.8 mm behind the glass.
struct CameraConfig;
void applyCameraPreset(CameraPreset preset, CameraConfig* config);

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
  // Image effects, all off by default (the renders stay byte-identical without them).
  bool motion_blur = false;  // camera.motion_blur: blur along the image motion during the exposure
  SensorNoiseModel noise_model = SensorNoiseModel::kWaterPreset;
  CameraSensorConfig sensor{};
  std::vector<ArmWindow> arm;  // camera.arm: the manipulator in front of the cameras

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
