#pragma once
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav {

// The panel "knowledge base" of the DexROV method: what navigation knows in advance about the oil & gas
// panel. Panel frame P: origin at the centre of the panel's footprint on the seabed, x along the front
// face's outward normal, y along the left face's outward normal, z up. Marker frame M (OpenCV ArUco):
// origin at the marker centre, x right and y up in the marker plane as seen from the front, z out of the
// face (towards a camera that sees it). Loaded by board/ (board/config/panel_file.h); nav only reads it.
struct PanelMarker {
  int id = 0;                                   // ArUco id
  int face = 0;                                 // index into PanelDescription::faces
  Eigen::Vector3d p_marker_in_panel_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_panel_marker = Eigen::Quaterniond::Identity();
};

struct PanelFace {
  std::string name;                             // "valves", "grasping", "plain"
  Eigen::Vector3d centre_in_panel_m = Eigen::Vector3d::Zero();  // centre of the face's rectangle
  Eigen::Vector3d normal_in_panel = Eigen::Vector3d::UnitX();   // outward unit normal
  double width_m = 2.0;
  double height_m = 1.5;
};

struct PanelDescription {
  std::string dictionary = "DICT_4X4_50";       // OpenCV predefined ArUco dictionary name
  double marker_size_m = 0.15;                  // black border side length
  double corner_radius_m = 0.15;                // rounded vertical edges between faces
  std::vector<PanelFace> faces;
  std::vector<PanelMarker> markers;

  const PanelMarker* marker(int id) const {
    for (const auto& m : markers) {
      if (m.id == id) return &m;
    }
    return nullptr;
  }
};

}  // namespace deepnav
