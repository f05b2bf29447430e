// Scene geometry of the stereo renderer: analytic ray-primitive intersections and the panel knowledge
// base (faces, marker frames) that the renderer paints and navigation reads.
#include <cmath>

#include <gtest/gtest.h>

#include "tools/sim/render/marker_layout.h"
#include "tools/sim/render/panel_faces.h"
#include "tools/sim/render/panel_knowledge.h"
#include "tools/sim/render/ray_primitives.h"
#include "tools/sim/render/seabed.h"

namespace deepnav::sim {
namespace {

Primitive makeShape(ShapeKind kind, Eigen::Vector3f lo, Eigen::Vector3f hi) {
  Primitive p;
  p.kind = kind;
  p.lo = lo;
  p.hi = hi;
  placePrimitive(Eigen::Matrix3f::Identity(), Eigen::Vector3f::Zero(), &p);
  return p;
}

TEST(SimRenderPrimitives, RayMeetsEachShapeWhereGeometrySays) {
  LocalHit hit;
  const Eigen::Vector3f o(0.0f, 0.0f, 5.0f), down(0.0f, 0.0f, -1.0f);
  // GIVEN shapes around the origin WHEN a ray comes straight down from z = 5 THEN it meets their top.
  const Primitive box = makeShape(ShapeKind::kBox, {-1, -1, -1}, {1, 1, 0.5f});
  ASSERT_TRUE(intersectBox(o, down, box, 0.0f, 100.0f, &hit));
  EXPECT_FLOAT_EQ(hit.t, 4.5f);
  EXPECT_FLOAT_EQ(hit.n.z(), 1.0f);
  const Primitive cyl = makeShape(ShapeKind::kCylinder, {-0.3f, -0.3f, 0.0f}, {0.3f, 0.3f, 2.0f});
  ASSERT_TRUE(intersectCylinder(o, down, cyl, 0.0f, 100.0f, &hit));
  EXPECT_FLOAT_EQ(hit.t, 3.0f);
  const Primitive ell = makeShape(ShapeKind::kEllipsoid, {}, {0.5f, 0.2f, 0.25f});
  ASSERT_TRUE(intersectEllipsoid(o, down, ell, 0.0f, 100.0f, &hit));
  EXPECT_NEAR(hit.t, 4.75f, 1e-5f);
  // A sideways ray meets the cylinder's side at its radius, with an outward normal.
  ASSERT_TRUE(intersectCylinder({5.0f, 0.0f, 1.0f}, {-2.0f, 0.0f, 0.0f}, cyl, 0.0f, 100.0f, &hit));
  EXPECT_NEAR(hit.t, 2.35f, 1e-5f);
  EXPECT_NEAR(hit.n.x(), 1.0f, 1e-6f);
  // The rect is two-sided: from below, its back.
  const Primitive rect = makeShape(ShapeKind::kRect, {-1, -1, 0}, {1, 1, 0});
  ASSERT_TRUE(intersectRect({0.5f, 0.5f, -2.0f}, {0.0f, 0.0f, 1.0f}, rect, 0.0f, 100.0f, &hit));
  EXPECT_TRUE(hit.back);
  EXPECT_FALSE(intersectRect({1.5f, 0.0f, 2.0f}, down, rect, 0.0f, 100.0f, &hit));
  // The arc is only the x, y >= 0 quarter: a ray along -x at y = 0.1 meets it from outside at x = r.
  const Primitive arc = makeShape(ShapeKind::kArc, {0, 0, 0}, {0.5f, 0.5f, 1.0f});
  ASSERT_TRUE(intersectArc({3.0f, 0.3f, 0.5f}, {-1.0f, 0.0f, 0.0f}, arc, 0.0f, 100.0f, &hit));
  EXPECT_NEAR(hit.t, 3.0f - 0.4f, 1e-5f);
  EXPECT_FALSE(hit.back);
  EXPECT_FALSE(intersectArc({3.0f, -0.3f, 0.5f}, {-1.0f, 0.0f, 0.0f}, arc, 0.0f, 100.0f, &hit));
  // t_max limits every test.
  EXPECT_FALSE(intersectBox(o, down, box, 0.0f, 4.0f, &hit));
}

TEST(SimRenderPanel, DescriptionHasThreeFacesAndMarkersOnThem) {
  Scenario s;
  const PanelDescription d = makePanelDescription(s);
  ASSERT_EQ(d.faces.size(), 3u);
  EXPECT_EQ(d.faces[0].name, "valves");
  EXPECT_EQ(d.faces[1].name, "grasping");
  EXPECT_EQ(d.faces[2].name, "plain");
  EXPECT_TRUE(d.faces[0].normal_in_panel.isApprox(Eigen::Vector3d::UnitY()));
  EXPECT_TRUE(d.faces[1].normal_in_panel.isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE(d.faces[0].centre_in_panel_m.isApprox(Eigen::Vector3d(0.0, 1.0, 0.75)));
  EXPECT_EQ(d.dictionary, "DICT_4X4_50");
  EXPECT_DOUBLE_EQ(d.marker_size_m, 0.15);
  ASSERT_EQ(d.markers.size(), 10u);
  const auto faces = panelFaces(s.panel);
  for (const PanelMarker& m : d.markers) {
    const PanelFace& f = d.faces[m.face];
    const Eigen::Matrix3d R = m.q_panel_marker.toRotationMatrix();
    // z of M is the face's outward normal, y is up, x = y cross z (right-handed, ArUco).
    EXPECT_TRUE(R.col(2).isApprox(f.normal_in_panel)) << m.id;
    EXPECT_TRUE(R.col(1).isApprox(Eigen::Vector3d::UnitZ())) << m.id;
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
    // On the face plane, on its flat part.
    EXPECT_NEAR((m.p_marker_in_panel_m - f.centre_in_panel_m).dot(f.normal_in_panel), 0.0, 1e-12) << m.id;
    const double along = (m.p_marker_in_panel_m - faces[m.face].origin_in_panel_m).dot(faces[m.face].right_in_panel);
    EXPECT_GT(along - 0.105, faces[m.face].s_min_m);
    EXPECT_LT(along + 0.105, faces[m.face].s_max_m);
  }
  s.panel.markers_enabled = false;
  EXPECT_TRUE(makePanelDescription(s).markers.empty());
}

TEST(SimRenderPanel, LayoutValidationNamesTheProblem) {
  PanelGeometry panel;
  std::string error;
  EXPECT_TRUE(validateMarkerLayout(defaultMarkerLayout(), panel, &error)) << error;
  MarkerLayout bad = defaultMarkerLayout();
  bad.spots[1].id = 60;  // DICT_4X4_50 has ids 0..49
  EXPECT_FALSE(validateMarkerLayout(bad, panel, &error));
  EXPECT_NE(error.find("marker 60"), std::string::npos) << error;
  bad = defaultMarkerLayout();
  bad.spots[0].z_fraction = 0.99;
  EXPECT_FALSE(validateMarkerLayout(bad, panel, &error));
  bad = defaultMarkerLayout();
  bad.dictionary = "DICT_NOPE";
  EXPECT_FALSE(validateMarkerLayout(bad, panel, &error));
}

TEST(SimRenderSeabed, MarchedHitLiesOnTheRelief) {
  Seabed seabed;
  ASSERT_TRUE(seabed.init(7));
  EXPECT_LT(seabed.minHeight_m(), 0.0f);
  EXPECT_GT(seabed.maxHeight_m(), 0.0f);
  // GIVEN rays from 1.3 m above the seabed at many slopes WHEN intersected THEN the hit is on z = h(x, y)
  // and no earlier sample along the ray is below the relief.
  const Eigen::Vector3f o(0.5f, 2.5f, 1.3f);
  for (int k = 0; k < 40; ++k) {
    const float slope = 0.06f + 0.05f * k;
    const Eigen::Vector3f d(std::cos(0.3f * k), std::sin(0.3f * k), -slope);
    float t = 0.0f;
    ASSERT_TRUE(seabed.intersect(o, d, 1e-3f, 1e3f, &t)) << k;
    const Eigen::Vector3f p = o + t * d;
    EXPECT_NEAR(p.z(), seabed.heightAt(p.x(), p.y()), 2e-4f) << k;
    for (float s = 0.0f; s < t; s += 0.002f * t) {
      const Eigen::Vector3f q = o + s * d;
      ASSERT_GT(q.z(), seabed.heightAt(q.x(), q.y()) - 1e-3f) << k << " " << s;
    }
  }
  // Looking up: nothing.
  float t = 0.0f;
  EXPECT_FALSE(seabed.intersect(o, Eigen::Vector3f(1.0f, 0.0f, 0.1f), 1e-3f, 1e3f, &t));
}

}  // namespace
}  // namespace deepnav::sim
