#pragma once
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/markers/panel_description.h"
#include "tools/sim/render/fish_school.h"
#include "tools/sim/render/manipulator_arm.h"
#include "tools/sim/render/material.h"
#include "tools/sim/render/primitive.h"
#include "tools/sim/render/ray_primitives.h"
#include "tools/sim/render/seabed.h"
#include "tools/sim/render/texture_map.h"
#include "tools/sim/scenario.h"

namespace deepnav::sim {

// Where a ray meets the scene: parameter t, the primitive (or kSeabed) and the local hit.
struct SceneHit {
  float t = 0.0f;
  int primitive = -1;
  LocalHit local;  // the seabed fills local.p and local.n (in P)
};

// The rendered world in the panel frame P (origin at the footprint centre on the seabed, x = front
// normal, y = left normal, z up): the seabed, the panel's three faces (rects 0, 1, 2 = valves, grasping,
// plain, painted with their markers) joined by two rounded corners and open at the back, the fixtures on
// the faces (panel_fixtures.h) and optional fish. Textures and relief come from the seed.
class Scene {
 public:
  static constexpr int kSeabed = -1;

  // quiet_zone_m: the white margin painted around each marker (MarkerLayout::quiet_zone_m).
  bool init(const Scenario& scenario, const PanelDescription& panel, double quiet_zone_m, std::uint64_t seed,
            std::string* error);
  // Moves the fish to time t.
  void setTime(double t_s);
  // Poses the manipulator arm (camera.arm, manipulator_arm.h; its primitives follow the fish) at time t
  // on the robot at R_panel_robot, p_robot_in_panel_m. Nothing without camera.arm.
  void placeArm(const Eigen::Matrix3f& R_panel_robot, const Eigen::Vector3f& p_robot_in_panel_m, double t_s);
  bool hasArm() const { return arm_.enabled(); }

  const std::vector<Primitive>& primitives() const { return primitives_; }
  const Seabed& seabed() const { return seabed_; }
  // The panel frame in the odometry (scene) frame: footprint centre on the seabed, yawed by front_yaw_deg.
  const Eigen::Isometry3d& T_odom_panel() const { return T_odom_panel_; }
  // Primitive index of face i's rect (its markers are painted on it).
  static int faceRect(int face) { return face; }

  // Nearest hit of o + t d (P) with t in (t_min, t_max) over everything, without culling: for queries
  // (visibility, tests); the renderer culls per tile and calls the same primitive tests.
  bool intersect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max,
                 SceneHit* hit) const;
  // Unit normal in P at a hit (turned towards the ray, except on the seabed: up).
  Eigen::Vector3f normalAt(const SceneHit& hit) const;
  // Albedo (B, G, R in lanes 0-2, lane 3 is 0) at a hit; footprint2_m2 is the squared size of a pixel
  // there, to choose the texture level.
  Eigen::Vector4f albedoAt(const SceneHit& hit, const Eigen::Vector3f& o, const Eigen::Vector3f& d,
                           float footprint2_m2) const;
  // The same for four hits (lanes) at once, bit for bit: sampled four at a time (TextureMap::sample4) when
  // all four are on the seabed or on the front of one textured rect, else per hit. px, py: the hits'
  // o + t d in P; d: the four rays.
  void albedo4(const SceneHit* hit, const Eigen::Vector3f& o, const Eigen::Vector3f* d, Float4 px, Float4 py,
               Float4 footprint2_m2, Eigen::Vector4f out[4]) const;

 private:
  bool buildPanel(const Scenario& scenario, const PanelDescription& panel, double quiet_zone_m, std::uint32_t seed,
                  std::string* error);
  void addFish(const Scenario& scenario, std::uint64_t seed);
  void addArm(const Scenario& scenario);

  std::vector<Primitive> primitives_;
  std::vector<Material> materials_;
  std::vector<TextureMap> textures_;
  Seabed seabed_;
  FishSchool fish_;
  int first_fish_ = 0;
  ManipulatorArm arm_;
  int first_arm_ = 0;
  Eigen::Isometry3d T_odom_panel_ = Eigen::Isometry3d::Identity();
};

// Inline: called once per pixel.
inline Eigen::Vector3f Scene::normalAt(const SceneHit& hit) const {
  if (hit.primitive == kSeabed) {  // filled by Seabed::intersect
    // Component by component: Seabed::refine stored them as three floats, and a whole-vector copy (an
    // 8-byte load over two of them) cannot be store-forwarded (a stall of a dozen cycles per pixel).
    const Eigen::Vector3f& n = hit.local.n;
    return Eigen::Vector3f(n.x(), n.y(), n.z());
  }
  return primitives_[hit.primitive].R_panel_local * hit.local.n;
}

inline Eigen::Vector4f Scene::albedoAt(const SceneHit& hit, const Eigen::Vector3f& o, const Eigen::Vector3f& d,
                                       float footprint2_m2) const {
  // In a register (see TextureMap::sampleLevel: no narrow stores read back by a wide load).
  const auto lanes = [](const Eigen::Vector3f& bgr) { return toVector4f(Float4{bgr.x(), bgr.y(), bgr.z(), 0.0f}); };
  if (hit.primitive == kSeabed) {
    const Eigen::Vector3f p = o + hit.t * d;
    return seabed_.albedoAt(p.x(), p.y(), footprint2_m2);
  }
  const Primitive& prim = primitives_[hit.primitive];
  const Material& m = materials_[prim.material];
  const Eigen::Vector3f& p = hit.local.p;
  if (m.kind == MaterialKind::kSolid) return lanes(m.albedo_bgr);
  if (hit.local.back) return lanes(m.back_albedo_bgr);
  const float u = m.kind == MaterialKind::kRectTexture ? (p.x() - m.u0_m) * m.texels_per_m
                                                       : std::atan2(p.y(), p.x()) * prim.hi.x() * m.texels_per_m;
  const float v = (m.v0_m - (m.kind == MaterialKind::kRectTexture ? p.y() : p.z())) * m.texels_per_m;
  return textures_[m.texture].sample(u, v, footprint2_m2 * m.texels_per_m * m.texels_per_m);
}

}  // namespace deepnav::sim
