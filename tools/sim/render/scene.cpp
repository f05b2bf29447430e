#include "tools/sim/render/scene.h"

#include <cmath>
#include <numbers>

#include "tools/sim/render/face_paint.h"
#include "tools/sim/render/panel_faces.h"
#include "tools/sim/render/panel_fixtures.h"
#include "tools/sim/render/procedural_noise.h"
#include "tools/sim/render/view_tick.h"

namespace deepnav::sim {

namespace {
const Eigen::Vector3f kBackAlbedo(0.12f, 0.12f, 0.13f);  // unpainted inside of the panel
const Eigen::Vector3f kFishAlbedo(0.30f, 0.30f, 0.28f);  // grey-silver
const Eigen::Vector3f kArmLinkAlbedo(0.30f, 0.32f, 0.34f);   // the manipulator's anodised links (BGR)
const Eigen::Vector3f kArmJointAlbedo(0.10f, 0.10f, 0.11f);  // its dark joints and gripper
}  // namespace

bool Scene::init(const Scenario& scenario, const PanelDescription& panel, double quiet_zone_m, std::uint64_t seed,
                 std::string* error) {
  primitives_.clear();
  materials_.clear();
  textures_.clear();
  T_odom_panel_ = panelPoseInOdom(scenario);
  const std::uint32_t seed32 = hashU32(static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32), 0x5CE7EU);
  if (!seabed_.init(seed32)) {
    if (error) *error = "renderer: seabed init failed";
    return false;
  }
  if (!buildPanel(scenario, panel, quiet_zone_m, seed32, error)) return false;
  addFish(scenario, seed);
  addArm(scenario);
  return true;
}

bool Scene::buildPanel(const Scenario& scenario, const PanelDescription& panel, double quiet_zone_m,
                       std::uint32_t seed, std::string* error) {
  const PanelGeometry& g = scenario.panel;
  const auto faces = panelFaces(g);
  FacePaintSpec spec;
  spec.z_bottom_m = seabed_.minHeight_m() - 0.02;  // the faces reach below the lowest relief
  spec.quiet_zone_m = quiet_zone_m;
  const float tpm = static_cast<float>(1.0 / spec.texel_m);
  textures_.reserve(kPanelFaceCount + 2);
  for (int i = 0; i < kPanelFaceCount; ++i) {
    const FaceFrame& f = faces[i];
    textures_.emplace_back();
    if (!paintFace(f, i, panel, spec, seed, &textures_.back(), error)) return false;
    Material m;
    m.kind = MaterialKind::kRectTexture;
    m.texture = i;
    m.texels_per_m = tpm;
    m.u0_m = static_cast<float>(-f.half_width_m);
    m.v0_m = static_cast<float>(f.height_m);
    m.back_albedo_bgr = kBackAlbedo;
    materials_.push_back(m);
    Primitive p;
    p.kind = ShapeKind::kRect;
    p.material = i;
    p.lo = Eigen::Vector3f(static_cast<float>(f.s_min_m), static_cast<float>(spec.z_bottom_m), 0.0f);
    p.hi = Eigen::Vector3f(static_cast<float>(f.s_max_m), static_cast<float>(f.height_m), 0.0f);
    placePrimitive(f.R_panel_face().cast<float>(), f.origin_in_panel_m.cast<float>(), &p);
    primitives_.push_back(p);
  }
  const double a = g.half_width_m, r = g.corner_radius_m;
  if (r > 0.0) {
    // Front-left corner: local axes = P's. Front-right: local x = -y of P, local y = x of P.
    Eigen::Matrix3f R_right;
    R_right << 0.0f, 1.0f, 0.0f, -1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f;
    const Eigen::Matrix3f rotations[2] = {Eigen::Matrix3f::Identity(), R_right};
    const float c = static_cast<float>(a - r);
    const Eigen::Vector3f centres[2] = {Eigen::Vector3f(c, c, 0.0f), Eigen::Vector3f(c, -c, 0.0f)};
    for (int k = 0; k < 2; ++k) {
      textures_.emplace_back();
      paintCorner(0.5 * std::numbers::pi * r, g.height_m, spec, seed + 101U * (k + 1), &textures_.back());
      Material m;
      m.kind = MaterialKind::kArcTexture;
      m.texture = static_cast<int>(textures_.size()) - 1;
      m.texels_per_m = tpm;
      m.v0_m = static_cast<float>(g.height_m);
      m.back_albedo_bgr = kBackAlbedo;
      materials_.push_back(m);
      Primitive p;
      p.kind = ShapeKind::kArc;
      p.material = static_cast<int>(materials_.size()) - 1;
      p.lo = Eigen::Vector3f(0.0f, 0.0f, static_cast<float>(spec.z_bottom_m));
      p.hi = Eigen::Vector3f(static_cast<float>(r), static_cast<float>(r), static_cast<float>(g.height_m));
      placePrimitive(rotations[k], centres[k], &p);
      primitives_.push_back(p);
    }
  }
  addPanelFixtures(faces, &primitives_, &materials_);
  return true;
}

void Scene::addFish(const Scenario& scenario, std::uint64_t seed) {
  fish_.init(scenario.water.fish_count, scenario.panel.half_width_m, scenario.trajectory.standoff_m, seed);
  Material m;
  m.albedo_bgr = kFishAlbedo;
  materials_.push_back(m);
  first_fish_ = static_cast<int>(primitives_.size());
  for (const FishSchool::Fish& f : fish_.fish()) {
    Primitive p;
    p.kind = ShapeKind::kEllipsoid;
    p.material = static_cast<int>(materials_.size()) - 1;
    p.hi = f.semi_axes_m;
    p.lo = -f.semi_axes_m;
    primitives_.push_back(p);
  }
  setTime(0.0);
}

void Scene::setTime(double t_s) {
  for (int i = 0; i < static_cast<int>(fish_.fish().size()); ++i) {
    Eigen::Matrix3f R;
    Eigen::Vector3f p;
    fish_.poseAt(i, t_s, &R, &p);
    placePrimitive(R, p, &primitives_[first_fish_ + i]);
  }
}

void Scene::addArm(const Scenario& scenario) {
  arm_.init(scenario.camera.arm);
  first_arm_ = static_cast<int>(primitives_.size());
  if (!arm_.enabled()) return;
  const int first_material = static_cast<int>(materials_.size());
  Material links, joints;
  links.albedo_bgr = kArmLinkAlbedo;
  joints.albedo_bgr = kArmJointAlbedo;
  materials_.push_back(links);
  materials_.push_back(joints);
  ManipulatorArm::Parts parts;
  arm_.partsAt(0.0, &parts);
  for (ManipulatorArm::Part& part : parts) {
    part.shape.material += first_material;
    primitives_.push_back(part.shape);
  }
  placeArm(Eigen::Matrix3f::Identity(), Eigen::Vector3f(0.0f, 0.0f, -100.0f), 0.0);
}

void Scene::placeArm(const Eigen::Matrix3f& R_panel_robot, const Eigen::Vector3f& p_robot_in_panel_m, double t_s) {
  if (!arm_.enabled()) return;
  ManipulatorArm::Parts parts;
  arm_.partsAt(t_s, &parts);
  for (int i = 0; i < ManipulatorArm::kParts; ++i)
    placePrimitive(R_panel_robot * parts[i].R_robot_part, p_robot_in_panel_m + R_panel_robot * parts[i].p_part_in_robot_m,
                   &primitives_[first_arm_ + i]);
}

bool Scene::intersect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max,
                      SceneHit* hit) const {
  bool found = false;
  LocalHit local;
  for (int i = 0; i < static_cast<int>(primitives_.size()); ++i) {
    const Primitive& p = primitives_[i];
    const Eigen::Vector3f o_local = p.R_local_panel * (o - p.p_local_in_panel_m);
    if (intersectPrimitive(o_local, p.R_local_panel * d, p, t_min, t_max, &local)) {
      t_max = local.t;
      hit->t = local.t;
      hit->primitive = i;
      hit->local = local;
      found = true;
    }
  }
  float t_seabed = 0.0f;
  if (seabed_.intersect(o, d, t_min, t_max, &t_seabed, &hit->local.n)) {
    hit->t = t_seabed;
    hit->primitive = kSeabed;
    hit->local.p = o + t_seabed * d;
    found = true;
  }
  return found;
}

void Scene::albedo4(const SceneHit* hit, const Eigen::Vector3f& o, const Eigen::Vector3f* d, Float4 px, Float4 py,
                    Float4 footprint2_m2, Eigen::Vector4f out[4]) const {
  const int p0 = hit[0].primitive;
  const bool same = p0 == hit[1].primitive && p0 == hit[2].primitive && p0 == hit[3].primitive;
  if (same && p0 == kSeabed) {
    seabed_.albedo4(px, py, footprint2_m2, out);
    return;
  }
  if (same && p0 >= 0) {
    const Material& m = materials_[primitives_[p0].material];
    const bool front = !(hit[0].local.back || hit[1].local.back || hit[2].local.back || hit[3].local.back);
    if (m.kind == MaterialKind::kRectTexture && front) {  // albedoAt's rect case, lane-wise
      const Float4 x{hit[0].local.p.x(), hit[1].local.p.x(), hit[2].local.p.x(), hit[3].local.p.x()};
      const Float4 y{hit[0].local.p.y(), hit[1].local.p.y(), hit[2].local.p.y(), hit[3].local.p.y()};
      textures_[m.texture].sample4((x - m.u0_m) * m.texels_per_m, (m.v0_m - y) * m.texels_per_m,
                                   footprint2_m2 * m.texels_per_m * m.texels_per_m, out);
      return;
    }
  }
  for (int i = 0; i < 4; ++i)
    out[i] = hit[i].primitive != -2 ? albedoAt(hit[i], o, d[i], footprint2_m2[i]) : Eigen::Vector4f::Zero();
}

}  // namespace deepnav::sim
