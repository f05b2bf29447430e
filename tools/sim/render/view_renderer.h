#pragma once
#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "tools/sim/render/float4.h"
#include "tools/sim/render/forward_scatter.h"
#include "tools/sim/render/scene.h"
#include "tools/sim/render/sediment_plume.h"
#include "tools/sim/render/water_column.h"
#include "tools/sim/render/water_optics.h"
#include "tools/sim/render/water_path.h"
#include "tools/sim/sensors/camera_rig.h"

namespace deepnav::sim {

// One camera's view of the scene for one frame, everything in the panel frame P.
struct ViewPose {
  Eigen::Matrix3f R_panel_cam = Eigen::Matrix3f::Identity();  // optical frame: z forward, x right, y down
  Eigen::Vector3f p_cam_in_panel_m = Eigen::Vector3f::Zero();
};

// The vehicle's two lamps (they move with the rig, so both cameras see the same lighting).
struct LampSet {
  std::array<Eigen::Vector3f, 2> p_lamp_in_panel_m{Eigen::Vector3f::Zero(), Eigen::Vector3f::Zero()};
  Eigen::Vector3f axis_in_panel = Eigen::Vector3f::UnitX();  // both aim along the optical axis
};

// Ray casts one pinhole camera: one ray per pixel centre, d = R_panel_cam (x_n, y_n, 1) with
// x_n = (u - cx) / fx, y_n = (v - cy) / fy, so the ray parameter of a hit is its depth along the
// optical axis. Per 16 x 16 tile, the primitives whose bounding sphere meets the tile's cone of rays are
// listed nearest first, and a pixel stops testing once the next sphere is farther than its hit; the
// seabed is marched only up to the nearest hit. Shading (README: image formation):
//   E_c  = sum_lamps I cos(theta_s) cos(phi) / d_l^2 exp(-beta_c (d_l + d))   light reaching the camera
//   L_c  = albedo_c E_c + B_inf_c (1 - exp(-beta_c d))                         plus backscatter
//   out  = L_c / (1 + x_n^2 + y_n^2)^2                                        cos^4 vignetting
// No hit within max range: L_c = B_inf_c. Grey: 0.114 B + 0.587 G + 0.299 R.
class ViewRenderer {
 public:
  static constexpr float kMaxRange_m = 40.0f;  // beyond, lamps and water leave nothing visible
  static constexpr int kTile = 16;

  bool init(const CameraConfig& camera, int channels, const WaterOptics& optics, const Scene* scene,
            std::string* error);
  // The deep-sea terms (after init; none by default): the beam's cut-off, the water column (lamp
  // backscatter and plumes, water_column.h; `plumes` must outlive the renderer and be set to the frame's
  // time before begin()) and the forward-scatter blur, applied by finishWater() once every band is drawn.
  void setWater(const WaterEffects& effects, const SedimentPlumes* plumes);
  void finishWater();
  const CameraConfig& camera() const { return camera_; }
  // radiance: width * height * channels floats; depth_m: width * height floats (0 = no hit).
  void render(const ViewPose& pose, const LampSet& lamps, float* radiance, float* depth_m);
  // The same in steps: begin() sets up the frame, then each renderTileRow(r), r < tileRows(), draws the
  // 16-pixel band of rows [16 r, 16 r + 16). The stereo renderer alternates the bands of its two cameras:
  // both see nearly the same texels and relief cells, which then come from the cache the second time
  // (3 MB of seabed texture, 2 MB per face, do not stay cached over a whole view).
  void begin(const ViewPose& pose, const LampSet& lamps, float* radiance, float* depth_m);
  int tileRows() const { return (camera_.height_px + kTile - 1) / kTile; }
  void renderTileRow(int row);

 private:
  // The rays of a tile: the cone around their mean for the bounding spheres, and the four planes
  // through the camera and two adjacent corner rays (normals pointing inside) for the boxes.
  struct Cone {
    Eigen::Vector3f axis;
    float cos_half_angle;
    std::array<Eigen::Vector3f, 4> side;
  };
  // True when the primitive's box lies wholly outside one side of the tile (no pixel can hit it).
  bool outsideTile(const Cone& cone, int primitive) const;
  // The ray of pixel (u, v) from origin_ in the panel frame, scaled so that its component along the
  // optical axis is 1 (the ray parameter of a hit is its depth): the one place a camera model enters.
  // Pinhole: d = R_panel_cam (x_n, y_n, 1), linear in (u, v). A non-pinhole model (a flat port's
  // refraction, tools/sim/render/flat_port.*) replaces this and must then also replace the two places
  // that rely on the linearity: tileCone() (corner rays bound the tile) and the per-candidate local
  // direction in intersectRow() (c.base + u c.du + v c.dv = R_local_panel d), and give origin_ per pixel.
  Eigen::Vector3f pixelRay(int u, int v) const {
    return ray_base_ + static_cast<float>(u) * ray_du_ + static_cast<float>(v) * ray_dv_;
  }
  Cone tileCone(int u0, int v0, int u1, int v1) const;
  void listCandidates(const Cone& cone);
  void renderTile(int u0, int v0, int u1, int v1);
  // Per pixel, pose-independent: the ray's length per unit depth |(x_n, y_n, 1)| (a hit's distance is
  // depth times it) and its inverse (cos of the angle off the axis, for the vignetting and the view angle).
  struct PixelRay {
    float inv_length;
    float length;
  };
  // The intersection pass of one row of a tile (pixels u0 + i, i < u1 - u0) fills these, the shading pass
  // reads them; padded to a multiple of 4 with no-hit entries for the packets.
  struct RowHits {
    std::array<SceneHit, kTile> hit;
    std::array<Eigen::Vector3f, kTile> d;
    std::array<Eigen::Vector2f, kTile> slope;  // the relief's slope at a seabed hit (normalised when shaded)
  };
  void intersectRow(int v, int u0, int u1, RowHits* row) const;
  // Radiance of pixels (u + i, v), i < 4, into radiance_: the shading equation (class comment) with the
  // pixels in the lanes of 4-float vectors for the geometry (hit point, normal, lamp vectors, the two
  // divisions and the lamp distances' square roots) and per pixel for the albedo and the water
  // transmittance (B, G, R in the lanes of one vector there). Every lane makes the same operations in the
  // same order as a scalar evaluation, so the result does not depend on the grouping.
  void shadePacket(int v, int u, int count, const SceneHit* hit, const Eigen::Vector3f* d,
                   const Eigen::Vector2f* slope) const;
  // The deep-sea shading of pixel (u, v) (README: deep-sea image formation): the surface term E (lamp
  // light, already through the water; ignored without a hit) and albedo, the water column at the hit
  // (water_column.h). Writes the radiance and, for the blur, the surface term and distance.
  [[gnu::always_inline]] void shadeDeepSea(int v, int u, bool hit, float distance_m, Float4 column, Float4 albedo, Float4 E,
                    Float4 transmittance, float cos4, float* out) const;

  CameraConfig camera_;
  float inv_fx_ = 1.0f;
  int channels_ = 1;
  const Scene* scene_ = nullptr;
  WaterOptics optics_;
  WaterPath water_;
  Eigen::Vector4f backscatter_ = Eigen::Vector4f::Zero();  // B_inf, lanes 0-2
  Float4 backscatter4_{};                                  // the same in a register
  std::vector<PixelRay> pixel_rays_;
  // Per frame.
  LampSet lamps_;
  float* radiance_ = nullptr;
  float* depth_m_ = nullptr;
  Eigen::Vector3f origin_ = Eigen::Vector3f::Zero();
  float seabed_top_m_ = 0.0f;  // a ray from above the relief still above it at its hit never met it
  Eigen::Vector3f ray_base_, ray_du_, ray_dv_;  // d(u, v) = base + u du + v dv
  std::vector<Eigen::Vector3f> origin_local_;     // per primitive
  std::vector<float> near_m_;                     // per primitive: distance to its bounding sphere
  // Per tile, nearest first: the primitive and its local ray direction d(u, v) = base + u du + v dv
  // (the camera ray's linear map taken into the primitive's frame once per tile).
  struct Candidate {
    int primitive;
    float near_m;
    Float4 base, du, dv;  // x, y, z in lanes 0-2: one SSE operation per term instead of three
  };
  std::vector<Candidate> candidates_;
  // Deep-sea water (setWater): off unless a term is on.
  WaterEffects effects_;
  bool deep_sea_ = false;  // the column or the blur: shadeDeepSea instead of the plain equation
  WaterColumn column_;
  ForwardScatter forward_scatter_;
  std::vector<float> direct_, distance_m_;  // per pixel, for the blur: surface radiance, hit distance
  float* direct_out_ = nullptr;             // their data, written by the (const) shading
  float* distance_out_ = nullptr;
};

}  // namespace deepnav::sim
