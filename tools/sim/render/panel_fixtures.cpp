#include "tools/sim/render/panel_fixtures.h"

namespace deepnav::sim {

namespace {

// Which face axis a round shape's axis (local z) follows.
enum class Axis { kNormal, kRight, kUp };

struct FixtureBuilder {
  const FaceFrame& face;
  std::vector<Primitive>* out;

  // Local frame at (s, z) on the face: columns chosen so that local z follows `axis`, right-handed.
  Eigen::Matrix3f rotation(Axis axis) const {
    const Eigen::Vector3f r = face.right_in_panel.cast<float>(), n = face.normal_in_panel.cast<float>();
    const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
    Eigen::Matrix3f R;
    if (axis == Axis::kNormal) R << r, up, n;
    if (axis == Axis::kRight) R << up, n, r;
    if (axis == Axis::kUp) R << n, r, up;
    return R;
  }
  Eigen::Vector3f at(double s_frac, double z_frac) const {
    return face.pointAt(s_frac * face.half_width_m, z_frac * face.height_m).cast<float>();
  }
  // A box spanning [s0, s1] x [z0, z1] (relative to the anchor) and [w0, w1] in front of the face.
  void box(double s_frac, double z_frac, Eigen::Vector3f lo, Eigen::Vector3f hi, int material) const {
    Primitive p;
    p.kind = ShapeKind::kBox;
    p.material = material;
    p.lo = lo, p.hi = hi;
    placePrimitive(rotation(Axis::kNormal), at(s_frac, z_frac), &p);
    out->push_back(p);
  }
  // A capped cylinder of radius r along `axis`, covering [a0, a1] along it. Its centre line is w in
  // front of the face (for kNormal, w is ignored: it starts at the face when a0 = 0).
  void cylinder(double s_frac, double z_frac, Axis axis, float radius, float a0, float a1, float w,
                int material) const {
    Primitive p;
    p.kind = ShapeKind::kCylinder;
    p.material = material;
    p.lo = Eigen::Vector3f(-radius, -radius, a0);
    p.hi = Eigen::Vector3f(radius, radius, a1);
    const Eigen::Vector3f offset = axis == Axis::kNormal ? Eigen::Vector3f::Zero()
                                                         : Eigen::Vector3f(face.normal_in_panel.cast<float>() * w);
    placePrimitive(rotation(axis), at(s_frac, z_frac) + offset, &p);
    out->push_back(p);
  }
};

int addSolid(std::vector<Material>* materials, float b, float g, float r) {
  Material m;
  m.kind = MaterialKind::kSolid;
  m.albedo_bgr = Eigen::Vector3f(b, g, r);
  materials->push_back(m);
  return static_cast<int>(materials->size()) - 1;
}

void addValvesFixtures(const FixtureBuilder& f, int dark_steel, int steel, int red, int orange) {
  using V = Eigen::Vector3f;
  // Rotary valve with a T-handle (1.3 m above the seabed on a 1.5 m panel).
  f.cylinder(-0.16, 0.867, Axis::kNormal, 0.075f, 0.0f, 0.045f, 0.0f, dark_steel);
  f.cylinder(-0.16, 0.867, Axis::kNormal, 0.014f, 0.045f, 0.11f, 0.0f, steel);
  f.box(-0.16, 0.867, V(-0.085f, -0.011f, 0.095f), V(0.085f, 0.011f, 0.12f), red);
  // Quarter-turn valve with a lever pointing right.
  f.box(0.1, 0.867, V(-0.065f, -0.065f, 0.0f), V(0.065f, 0.065f, 0.05f), dark_steel);
  f.cylinder(0.1, 0.867, Axis::kNormal, 0.012f, 0.05f, 0.075f, 0.0f, steel);
  f.box(0.1, 0.867, V(-0.02f, -0.012f, 0.075f), V(0.17f, 0.012f, 0.095f), orange);
  // Handwheel valve (the wheel as a disc), below them.
  f.cylinder(-0.02, 0.713, Axis::kNormal, 0.05f, 0.0f, 0.04f, 0.0f, dark_steel);
  f.cylinder(-0.02, 0.713, Axis::kNormal, 0.012f, 0.04f, 0.09f, 0.0f, steel);
  f.cylinder(-0.02, 0.713, Axis::kNormal, 0.085f, 0.09f, 0.11f, 0.0f, red);
  // A pipe along the face, low down (seen on the approach), held by two clamps.
  const float half_len = static_cast<float>(0.75 * f.face.half_width_m);
  f.cylinder(0.0, 0.22, Axis::kRight, 0.04f, -half_len, half_len, 0.06f, steel);
  for (double s : {-0.5, 0.5}) f.box(s, 0.22, V(-0.03f, -0.055f, 0.0f), V(0.03f, 0.055f, 0.105f), dark_steel);
}

void addGraspingFixtures(const FixtureBuilder& f, int dark_steel, int steel, int black, int orange) {
  using V = Eigen::Vector3f;
  const float a = static_cast<float>(f.face.half_width_m);
  const float h = static_cast<float>(f.face.height_m);
  // Handrail at 0.93 m on three brackets.
  f.cylinder(0.0, 0.62, Axis::kRight, 0.018f, -0.75f * a, 0.75f * a, 0.075f, steel);
  for (double s : {-0.7, 0.0, 0.7}) f.box(s, 0.62, V(-0.012f, -0.015f, 0.0f), V(0.012f, 0.015f, 0.075f), dark_steel);
  // Two vertical handles from 1.0 m to 1.42 m, each on two brackets.
  for (double s : {-0.15, 0.15}) {
    f.cylinder(s, 0.667, Axis::kUp, 0.016f, 0.0f, 0.28f * h, 0.065f, black);
    for (double z : {0.68, 0.933}) f.box(s, z, V(-0.012f, -0.012f, 0.0f), V(0.012f, 0.012f, 0.065f), dark_steel);
  }
  // U grasp bar between the handles.
  f.cylinder(0.0, 0.8, Axis::kRight, 0.013f, -0.07f, 0.07f, 0.07f, orange);
  for (float s : {-0.07f, 0.07f}) f.box(0.0, 0.8, V(s - 0.01f, -0.01f, 0.0f), V(s + 0.01f, 0.01f, 0.07f), orange);
  // Lower bar on two brackets.
  f.cylinder(0.0, 0.3, Axis::kRight, 0.025f, -0.6f * a, 0.6f * a, 0.08f, steel);
  for (double s : {-0.55, 0.55}) f.box(s, 0.3, V(-0.015f, -0.02f, 0.0f), V(0.015f, 0.02f, 0.08f), dark_steel);
}

}  // namespace

void addPanelFixtures(const std::array<FaceFrame, kPanelFaceCount>& faces, std::vector<Primitive>* primitives,
                      std::vector<Material>* materials) {
  const int dark_steel = addSolid(materials, 0.20f, 0.20f, 0.21f);
  const int steel = addSolid(materials, 0.42f, 0.42f, 0.43f);
  const int red = addSolid(materials, 0.06f, 0.08f, 0.50f);
  const int orange = addSolid(materials, 0.04f, 0.30f, 0.70f);
  const int black = addSolid(materials, 0.05f, 0.05f, 0.05f);
  addValvesFixtures(FixtureBuilder{faces[0], primitives}, dark_steel, steel, red, orange);
  addGraspingFixtures(FixtureBuilder{faces[1], primitives}, dark_steel, steel, black, orange);
}

}  // namespace deepnav::sim
