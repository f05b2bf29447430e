#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "board/config/board_config.h"
#include "nav/markers/panel_description.h"
#include "vision/calib/stereo_rectification.h"
#include "vision/pipeline/vision_pipeline.h"

namespace deepnav {

// Everything the loop is configured from: the board and, when the board names one, the panel
// description. The texts are kept so that a recording stores exactly what the run used.
struct VehicleSetup {
  BoardConfig config;
  std::string board_text;
  bool has_panel = false;
  PanelDescription panel;
  std::string panel_text;
  // camera.calibration_file's text (kept for the recording) and the rectification maps built from it
  // with camera.port.* at start-up; rectify is false when the board names no calibration (frames arrive
  // rectified with the camera.* intrinsics).
  std::string calibration_text;
  bool rectify = false;
  StereoRectification rectification;
};

// Loads a board file and the panel file it names (relative to the board file's folder).
bool loadVehicleSetup(const std::string& board_path, VehicleSetup* setup, std::string* error);
// The same from texts already in memory (a recording's metadata); panel_text and calibration_text may be
// empty (a board naming camera.calibration_file then fails: the calibration is missing).
bool parseVehicleSetup(const std::string& board_text, const std::string& panel_text, const std::string& name,
                       VehicleSetup* setup, std::string* error, const std::string& calibration_text = {});
// (Re)builds setup->rectification from setup->config and setup->calibration_text (start-up; PinAx maps
// take a few hundred ms). Called by the loaders and after board overrides.
bool buildSetupRectification(const std::string& name, VehicleSetup* setup, std::string* error);

// The metadata records a recording stores so that a replay runs with the same setup.
std::vector<std::pair<std::string, std::map<std::string, std::string>>> recordingMetadata(const VehicleSetup& setup);
// The setup stored in a recording by recordingMetadata() (deepnav.board, deepnav.panel,
// deepnav.calibration); *found false (setup untouched) when it holds none.
bool setupFromMetadata(const std::map<std::string, std::string>* board, const std::map<std::string, std::string>* panel,
                       const std::string& name, VehicleSetup* setup, std::string* error, bool* found,
                       const std::map<std::string, std::string>* calibration = nullptr);
inline constexpr const char* kCalibrationMetadata = "deepnav.calibration";

// The vision worker's configuration: image size, marker detection when there is a panel, and the
// rectification maps when the board names a calibration (the rectified intrinsics then replace camera.*).
VisionPipelineConfig visionConfig(const VehicleSetup& setup);

// Camera optical frame (z forward, x right, y down) in the robot frame, from camera.* of the board.
Eigen::Isometry3d robotFromCamera(const BoardConfig& config);
// The frame the vision results are in: the rectified left camera when the setup rectifies (rotated by
// the rectification and, with PinAx, moved to the virtual pinhole on the axis), else robotFromCamera.
Eigen::Isometry3d robotFromCamera(const VehicleSetup& setup);

}  // namespace deepnav
