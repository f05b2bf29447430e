#pragma once
#include <array>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tools/sim/panel_geometry.h"

namespace deepnav::sim {

// The panel's three faces, in the order of PanelDescription::faces and of the dive:
//   0 "valves"   the left face (outward normal +y of the panel frame P), met first by the trajectory;
//   1 "grasping" the front face (+x);
//   2 "plain"    the right face (-y), nearly textureless.
// Face frame F: x = r (to the right as seen from outside, = z cross n), y = up (z of P), z = n. A point
// of the face plane is origin + s r + z up, s along the face from its centre line, z above the seabed.
struct FaceFrame {
  std::string name;
  Eigen::Vector3d normal_in_panel = Eigen::Vector3d::UnitX();
  Eigen::Vector3d right_in_panel = Eigen::Vector3d::UnitY();
  Eigen::Vector3d origin_in_panel_m = Eigen::Vector3d::Zero();  // n * half_width, on the seabed
  double half_width_m = 1.0;  // the face's nominal half width (its rectangle is 2 half_width wide)
  double height_m = 1.5;
  double s_min_m = -1.0;      // the flat part, along r (the rest is the rounded corner or nothing)
  double s_max_m = 1.0;

  // A point at (s, z) on the face, w metres in front of it.
  Eigen::Vector3d pointAt(double s_m, double z_m, double w_m = 0.0) const;
  // Columns r, up, n: the rotation of the face frame (and of a marker on it) in P.
  Eigen::Matrix3d R_panel_face() const;
};

constexpr int kPanelFaceCount = 3;
std::array<FaceFrame, kPanelFaceCount> panelFaces(const PanelGeometry& panel);

}  // namespace deepnav::sim
