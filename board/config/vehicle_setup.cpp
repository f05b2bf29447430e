#include "board/config/vehicle_setup.h"

#include <filesystem>

#include "board/config/camera_rectification.h"
#include "board/config/panel_file.h"
#include "board/config/text_file.h"
#include "drivers/clock/monotonic_clock.h"

namespace deepnav {

bool buildSetupRectification(const std::string& name, VehicleSetup* s, std::string* error) {
  s->rectify = !s->config.camera.calibration_file.empty();
  s->rectification = StereoRectification{};
  if (!s->rectify) return true;
  if (s->calibration_text.empty()) {
    if (error)
      *error = name + ": camera.calibration_file names '" + s->config.camera.calibration_file +
               "' but the calibration is not available (not stored with this board)";
    return false;
  }
  return buildCameraRectificationFromText(s->config, s->calibration_text,
                                          name + " (" + s->config.camera.calibration_file + ")", &s->rectification,
                                          error);
}

bool parseVehicleSetup(const std::string& board_text, const std::string& panel_text, const std::string& name,
                       VehicleSetup* s, std::string* error, const std::string& calibration_text) {
  s->board_text = board_text;
  s->panel_text = panel_text;
  s->calibration_text = calibration_text;
  if (!loadBoardConfigText(board_text, name, &s->config, error)) return false;
  s->has_panel = !panel_text.empty();
  if (s->has_panel && !parsePanelDescription(panel_text, name + " (panel)", &s->panel, error)) return false;
  return buildSetupRectification(name, s, error);
}

bool loadVehicleSetup(const std::string& board_path, VehicleSetup* s, std::string* error) {
  std::string board_text;
  if (!readTextFile(board_path, "the board file", &board_text, error) ||
      !loadBoardConfigText(board_text, board_path, &s->config, error)) {
    return false;
  }
  const auto board_dir = std::filesystem::path(board_path).parent_path();
  std::string calibration_text;
  if (!s->config.camera.calibration_file.empty() &&
      !readTextFile((board_dir / s->config.camera.calibration_file).string(),
                    "the stereo calibration (camera.calibration_file)", &calibration_text, error)) {
    return false;
  }
  std::string panel_text;
  if (!s->config.markers.panel_file.empty()) {
    const auto panel_path = board_dir / s->config.markers.panel_file;
    if (!readTextFile(panel_path.string(), "the panel description (markers.panel_file)", &panel_text, error)) {
      return false;
    }
    return parseVehicleSetup(board_text, panel_text, panel_path.string(), s, error, calibration_text);
  }
  return parseVehicleSetup(board_text, panel_text, board_path, s, error, calibration_text);
}

std::vector<std::pair<std::string, std::map<std::string, std::string>>> recordingMetadata(const VehicleSetup& s) {
  std::vector<std::pair<std::string, std::map<std::string, std::string>>> out;
  out.push_back({"deepnav.board", {{"yaml", s.board_text}}});
  if (s.has_panel) out.push_back({"deepnav.panel", {{"yaml", s.panel_text}}});
  if (!s.calibration_text.empty()) out.push_back({kCalibrationMetadata, {{"yaml", s.calibration_text}}});
  return out;
}

bool setupFromMetadata(const std::map<std::string, std::string>* board, const std::map<std::string, std::string>* panel,
                       const std::string& name, VehicleSetup* setup, std::string* error, bool* found,
                       const std::map<std::string, std::string>* calibration) {
  *found = board && board->count("yaml");
  if (!*found) return true;
  const std::string panel_text = panel && panel->count("yaml") ? panel->at("yaml") : std::string();
  const std::string calibration_text =
      calibration && calibration->count("yaml") ? calibration->at("yaml") : std::string();
  return parseVehicleSetup(board->at("yaml"), panel_text, name, setup, error, calibration_text);
}

VisionPipelineConfig visionConfig(const VehicleSetup& s) {
  VisionPipelineConfig v = s.config.vision;  // the vision.* keys
  const BoardConfig::Camera& cam = s.config.camera;
  v.width_px = cam.width_px;
  v.height_px = cam.height_px;
  v.channels = cam.channels;
  v.detect_markers = s.has_panel && s.config.markers.enabled;
  v.markers.dictionary = s.panel.dictionary;
  v.markers.marker_size_m = s.panel.marker_size_m;
  v.markers.camera.fx_px = cam.fx_px;
  v.markers.camera.fy_px = cam.fy_px;
  v.markers.camera.cx_px = cam.cx_px;
  v.markers.camera.cy_px = cam.cy_px;
  v.rig.fx_px = cam.fx_px;
  v.rig.fy_px = cam.fy_px;
  v.rig.cx_px = cam.cx_px;
  v.rig.cy_px = cam.cy_px;
  v.rig.baseline_m = cam.baseline_m;
  v.clock_us = &monotonicUs;
  if (s.rectify) {
    v.rectify = true;
    v.rectification = s.rectification;
    const PinholeIntrinsics& k = s.rectification.rectified;
    v.markers.camera = k;
    v.rig.fx_px = k.fx_px;
    v.rig.fy_px = k.fy_px;
    v.rig.cx_px = k.cx_px;
    v.rig.cy_px = k.cy_px;
    v.rig.baseline_m = s.rectification.baseline_m;
  }
  return v;
}

Eigen::Isometry3d robotFromCamera(const BoardConfig& c) {
  Eigen::Matrix3d body_from_optical;
  body_from_optical << 0, 0, 1,  //
      -1, 0, 0,                  //
      0, -1, 0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = c.camera.q_robot_body.toRotationMatrix() * body_from_optical;
  T.translation() = c.camera.p_cam_in_robot_m;
  return T;
}

Eigen::Isometry3d robotFromCamera(const VehicleSetup& s) {
  const Eigen::Isometry3d T_robot_cam = robotFromCamera(s.config);
  if (!s.rectify) return T_robot_cam;
  // p_cam = R_rect_left^T p_rect + z_v e_z (vision/calib/stereo_rectification.h).
  Eigen::Isometry3d T_cam_rect = Eigen::Isometry3d::Identity();
  const cv::Matx33d& R = s.rectification.R_rect_left;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T_cam_rect.linear()(i, j) = R(j, i);
  T_cam_rect.translation() = Eigen::Vector3d(0.0, 0.0, s.rectification.virtual_centre_z_m);
  return T_robot_cam * T_cam_rect;
}

}  // namespace deepnav
