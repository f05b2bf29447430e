#pragma once
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "board/config/board_config.h"
#include "nav/markers/panel_description.h"
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
};

// Loads a board file and the panel file it names (relative to the board file's folder).
bool loadVehicleSetup(const std::string& board_path, VehicleSetup* setup, std::string* error);
// The same from texts already in memory (a recording's metadata); panel_text may be empty.
bool parseVehicleSetup(const std::string& board_text, const std::string& panel_text, const std::string& name,
                       VehicleSetup* setup, std::string* error);

// The metadata records a recording stores so that a replay runs with the same setup.
std::vector<std::pair<std::string, std::map<std::string, std::string>>> recordingMetadata(const VehicleSetup& setup);
// The setup stored in a recording by recordingMetadata(); false (setup untouched) when it holds none.
bool setupFromMetadata(const std::map<std::string, std::string>* board, const std::map<std::string, std::string>* panel,
                       const std::string& name, VehicleSetup* setup, std::string* error, bool* found);

// The vision worker's configuration: image size, and marker detection when there is a panel.
VisionPipelineConfig visionConfig(const VehicleSetup& setup);

// Camera optical frame (z forward, x right, y down) in the robot frame, from camera.* of the board.
Eigen::Isometry3d robotFromCamera(const BoardConfig& config);

}  // namespace deepnav
