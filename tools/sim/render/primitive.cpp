#include "tools/sim/render/primitive.h"

namespace deepnav::sim {

void placePrimitive(const Eigen::Matrix3f& R_panel_local, const Eigen::Vector3f& p_local_in_panel_m,
                    Primitive* p) {
  p->R_panel_local = R_panel_local;
  p->R_local_panel = R_panel_local.transpose();
  p->p_local_in_panel_m = p_local_in_panel_m;
  Eigen::Vector3f lo = p->lo, hi = p->hi;
  if (p->kind == ShapeKind::kCylinder || p->kind == ShapeKind::kArc) {
    // The bounds of a round shape are its radius in x and y.
    lo.head<2>() = Eigen::Vector2f(-hi.x(), -hi.x());
    hi.y() = hi.x();
  }
  if (p->kind == ShapeKind::kEllipsoid) lo = -hi;
  p->bound_centre_in_panel_m = p_local_in_panel_m + R_panel_local * (0.5f * (lo + hi));
  p->bound_radius_m = 0.5f * (hi - lo).norm();
  if (p->kind == ShapeKind::kRect) lo.z() = hi.z() = 0.0f;
  p->box_centre_local = 0.5f * (lo + hi);
  p->box_half_local = 0.5f * (hi - lo);
}

}  // namespace deepnav::sim
