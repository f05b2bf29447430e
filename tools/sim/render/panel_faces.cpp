#include "tools/sim/render/panel_faces.h"

namespace deepnav::sim {

Eigen::Vector3d FaceFrame::pointAt(double s_m, double z_m, double w_m) const {
  return origin_in_panel_m + s_m * right_in_panel + z_m * Eigen::Vector3d::UnitZ() + w_m * normal_in_panel;
}

Eigen::Matrix3d FaceFrame::R_panel_face() const {
  Eigen::Matrix3d R;
  R.col(0) = right_in_panel;
  R.col(1) = Eigen::Vector3d::UnitZ();
  R.col(2) = normal_in_panel;
  return R;
}

std::array<FaceFrame, kPanelFaceCount> panelFaces(const PanelGeometry& panel) {
  const double a = panel.half_width_m, r = panel.corner_radius_m;
  const std::array<const char*, kPanelFaceCount> names{"valves", "grasping", "plain"};
  const std::array<Eigen::Vector3d, kPanelFaceCount> normals{Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitX(),
                                                            -Eigen::Vector3d::UnitY()};
  std::array<FaceFrame, kPanelFaceCount> faces;
  for (int i = 0; i < kPanelFaceCount; ++i) {
    FaceFrame& f = faces[i];
    f.name = names[i];
    f.normal_in_panel = normals[i];
    f.right_in_panel = Eigen::Vector3d::UnitZ().cross(normals[i]);
    f.origin_in_panel_m = a * normals[i];
    f.half_width_m = a;
    f.height_m = panel.height_m;
  }
  // Left face: s = -x, from the open back (x = -a) to the front-left corner (x = a - r).
  faces[0].s_min_m = -(a - r), faces[0].s_max_m = a;
  // Front face: s = y, between the two corners.
  faces[1].s_min_m = -(a - r), faces[1].s_max_m = a - r;
  // Right face: s = x, from the open back to the front-right corner.
  faces[2].s_min_m = -a, faces[2].s_max_m = a - r;
  return faces;
}

}  // namespace deepnav::sim
