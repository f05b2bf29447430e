#pragma once
#include <string>

#include "nav/markers/panel_description.h"

namespace deepnav {

// Reads a panel description (knowledge base) YAML file; errors name the file and key. Format:
//   dictionary: DICT_4X4_50        # OpenCV predefined ArUco dictionary
//   marker_size_m: 0.15
//   corner_radius_m: 0.15
//   faces:
//     - {name: valves, centre_in_panel_m: [0, 1, 0.75], normal_in_panel: [0, 1, 0], width_m: 2, height_m: 1.5}
//   markers:
//     - {id: 0, face: 0, p_marker_in_panel_m: [x, y, z], q_panel_marker_xyzw: [x, y, z, w]}
bool loadPanelDescription(const std::string& path, PanelDescription* out, std::string* error);
bool parsePanelDescription(const std::string& yaml_text, const std::string& name, PanelDescription* out,
                           std::string* error);

// Writes the same format (the simulator writes the panel it renders).
bool writePanelDescription(const std::string& path, const PanelDescription& panel, std::string* error);
std::string formatPanelDescription(const PanelDescription& panel);

}  // namespace deepnav
