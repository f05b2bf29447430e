#pragma once
#include <cstdint>

#include <Eigen/Core>

namespace deepnav::sim {

enum class ShapeKind : std::uint8_t { kRect, kArc, kBox, kCylinder, kEllipsoid };

// One analytic shape of the scene, defined in its own local frame L and placed in the panel frame P.
// The local bounds [lo, hi] enclose the shape and, with the kind, define it:
//   kRect      the rectangle z = 0, x in [lo.x, hi.x], y in [lo.y, hi.y]; its front side faces +z.
//   kArc       the quarter cylinder x^2 + y^2 = hi.x^2, x >= 0, y >= 0, z in [lo.z, hi.z]; front outward.
//   kBox       the box [lo, hi].
//   kCylinder  the capped cylinder of radius hi.x about the z axis, z in [lo.z, hi.z].
//   kEllipsoid the ellipsoid of semi-axes hi centred at the origin.
struct Primitive {
  ShapeKind kind = ShapeKind::kBox;
  int material = 0;                                                 // index into Scene::materials()
  Eigen::Matrix3f R_panel_local = Eigen::Matrix3f::Identity();      // columns: local axes in P
  Eigen::Matrix3f R_local_panel = Eigen::Matrix3f::Identity();      // its transpose, for ray transforms
  Eigen::Vector3f p_local_in_panel_m = Eigen::Vector3f::Zero();
  Eigen::Vector3f lo = Eigen::Vector3f::Zero();
  Eigen::Vector3f hi = Eigen::Vector3f::Zero();
  Eigen::Vector3f bound_centre_in_panel_m = Eigen::Vector3f::Zero();  // bounding sphere (culling)
  float bound_radius_m = 0.0f;
  // The box the shape fills in L (rect: zero thickness; round shapes: their radius in x and y), as
  // centre and half extents: the renderer culls it against each tile's frustum.
  Eigen::Vector3f box_centre_local = Eigen::Vector3f::Zero();
  Eigen::Vector3f box_half_local = Eigen::Vector3f::Zero();
};

// Sets the pose (and the derived transpose and bounding sphere) of a primitive.
void placePrimitive(const Eigen::Matrix3f& R_panel_local, const Eigen::Vector3f& p_local_in_panel_m,
                    Primitive* p);

}  // namespace deepnav::sim
