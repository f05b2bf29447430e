#pragma once
#include <string>
#include <vector>

#include <opencv2/aruco.hpp>

#include "tools/sim/panel_geometry.h"

namespace deepnav::sim {

// Where the fiducial markers sit on the panel faces. Positions scale with the panel: the centre of a
// marker is at s = s_fraction * half_width along the face (to the right as seen from outside) and
// z = z_fraction * height above the seabed.
struct MarkerSpot {
  int id = 0;            // ArUco id, within the dictionary
  int face = 0;          // 0 valves (left), 1 grasping (front), 2 plain (right); see panel_faces.h
  double s_fraction = 0.0;
  double z_fraction = 0.5;
};

struct MarkerLayout {
  std::string dictionary = "DICT_4X4_50";  // OpenCV predefined ArUco dictionary name
  double marker_size_m = 0.15;             // black border side
  double quiet_zone_m = 0.025;             // white margin around the black border, each side
  std::vector<MarkerSpot> spots;
};

// 4 markers on each textured face (ids 0-3 valves, 4-7 grasping), 2 on the plain face (8, 9), placed
// for the dive's dwell poses (see the .cpp): at least one per camera there, all of a face from 1.5 m.
MarkerLayout defaultMarkerLayout();

// The OpenCV predefined dictionary of a name such as "DICT_4X4_50"; null for an unknown name.
cv::Ptr<cv::aruco::Dictionary> arucoDictionaryByName(const std::string& name);

// False with a message when the dictionary is unknown, an id is out of the dictionary or repeated, or a
// marker with its quiet zone does not fit on the flat part of its face.
bool validateMarkerLayout(const MarkerLayout& layout, const PanelGeometry& panel, std::string* error);

}  // namespace deepnav::sim
