#include "tools/sim/render/view_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "tools/sim/render/float4.h"

namespace deepnav::sim {

namespace {
constexpr float kTMin = 1e-3f;
}  // namespace

bool ViewRenderer::init(const CameraConfig& camera, int channels, const WaterOptics& optics, const Scene* scene,
                        std::string* error) {
  if ((channels != 1 && channels != 3) || scene == nullptr || camera.width_px < 16 || camera.height_px < 16) {
    if (error) *error = "renderer: channels must be 1 or 3 and the image at least 16 x 16";
    return false;
  }
  camera_ = camera;
  inv_fx_ = static_cast<float>(1.0 / camera.fx_px);
  channels_ = channels;
  scene_ = scene;
  optics_ = optics;
  // A lamp path plus the view path, both within range.
  water_.init(optics, 2.5f * kMaxRange_m);
  backscatter_ = Eigen::Vector4f(optics.backscatter[0], optics.backscatter[1], optics.backscatter[2], 0.0f);
  backscatter4_ = Float4{optics.backscatter[0], optics.backscatter[1], optics.backscatter[2], 0.0f};
  const std::size_t n = scene->primitives().size();
  origin_local_.assign(n, Eigen::Vector3f::Zero());
  near_m_.assign(n, 0.0f);
  candidates_.reserve(n);
  // |(x_n, y_n, 1)| per pixel and its inverse: the ray's length per unit depth, for distances and vignetting.
  // Plus 3 entries: the shading reads rays 4 at a time, and the image's last packet may be partial.
  pixel_rays_.assign(static_cast<std::size_t>(camera.width_px) * camera.height_px + 3, PixelRay{1.0f, 1.0f});
  for (int v = 0; v < camera.height_px; ++v) {
    const double yn = (v - camera.cy_px) / camera.fy_px;
    for (int u = 0; u < camera.width_px; ++u) {
      const double xn = (u - camera.cx_px) / camera.fx_px;
      const double length = std::sqrt(1.0 + xn * xn + yn * yn);
      pixel_rays_[static_cast<std::size_t>(v) * camera.width_px + u] = {static_cast<float>(1.0 / length),
                                                                         static_cast<float>(length)};
    }
  }
  return true;
}

void ViewRenderer::render(const ViewPose& pose, const LampSet& lamps, float* radiance, float* depth_m) {
  begin(pose, lamps, radiance, depth_m);
  for (int row = 0; row < tileRows(); ++row) renderTileRow(row);
}

void ViewRenderer::begin(const ViewPose& pose, const LampSet& lamps, float* radiance, float* depth_m) {
  const auto& prims = scene_->primitives();
  lamps_ = lamps;
  radiance_ = radiance;
  depth_m_ = depth_m;
  origin_ = pose.p_cam_in_panel_m;
  const float relief_top_m = scene_->seabed().maxHeight_m();
  seabed_top_m_ = origin_.z() > relief_top_m ? relief_top_m : INFINITY;
  for (std::size_t i = 0; i < prims.size(); ++i) {
    origin_local_[i] = prims[i].R_local_panel * (origin_ - prims[i].p_local_in_panel_m);
    near_m_[i] = std::max(0.0f, (prims[i].bound_centre_in_panel_m - origin_).norm() - prims[i].bound_radius_m);
  }
  const float fx = static_cast<float>(camera_.fx_px), fy = static_cast<float>(camera_.fy_px);
  ray_du_ = pose.R_panel_cam.col(0) / fx;
  ray_dv_ = pose.R_panel_cam.col(1) / fy;
  ray_base_ = pose.R_panel_cam.col(2) - static_cast<float>(camera_.cx_px) * ray_du_ -
              static_cast<float>(camera_.cy_px) * ray_dv_;
  if (effects_.column())
    column_.prepare(origin_, ray_base_, ray_du_, ray_dv_, lamps.p_lamp_in_panel_m, lamps.axis_in_panel);
}

void ViewRenderer::setWater(const WaterEffects& effects, const SedimentPlumes* plumes) {
  effects_ = effects;
  deep_sea_ = effects.column() || effects.forward_scatter_rad_per_m > 0.0f;
  const int w = camera_.width_px, h = camera_.height_px;
  if (effects.column()) column_.init(w, h, optics_, effects, plumes);
  if (effects.forward_scatter_rad_per_m > 0.0f) {
    forward_scatter_.init(w, h, channels_, static_cast<float>(camera_.fx_px), effects);
    direct_.assign(static_cast<std::size_t>(w) * h * channels_, 0.0f);
    distance_m_.assign(static_cast<std::size_t>(w) * h, 0.0f);
    direct_out_ = direct_.data();
    distance_out_ = distance_m_.data();
  }
}

void ViewRenderer::finishWater() {
  if (effects_.forward_scatter_rad_per_m > 0.0f) forward_scatter_.apply(direct_.data(), distance_m_.data(), radiance_);
}

void ViewRenderer::renderTileRow(int row) {
  const int w = camera_.width_px, h = camera_.height_px;
  const int v0 = row * kTile, v1 = std::min(v0 + kTile, h);
  for (int u0 = 0; u0 < w; u0 += kTile) {
    const int u1 = std::min(u0 + kTile, w);
    listCandidates(tileCone(u0, v0, u1, v1));
    renderTile(u0, v0, u1, v1);
  }
}

ViewRenderer::Cone ViewRenderer::tileCone(int u0, int v0, int u1, int v1) const {
  // Rays through the tile's outer pixel edges bound every ray of the tile (the tile is convex).
  const float us[2] = {u0 - 0.5f, u1 - 0.5f}, vs[2] = {v0 - 0.5f, v1 - 0.5f};
  Eigen::Vector3f corners[4];
  Eigen::Vector3f sum = Eigen::Vector3f::Zero();
  for (int k = 0; k < 4; ++k) {
    corners[k] = (ray_base_ + us[k & 1] * ray_du_ + vs[k >> 1] * ray_dv_).normalized();
    sum += corners[k];
  }
  Cone cone{sum.normalized(), 1.0f, {}};
  for (const auto& c : corners) cone.cos_half_angle = std::min(cone.cos_half_angle, cone.axis.dot(c));
  // Corners in order around the tile: 0 (u0, v0), 1 (u1, v0), 3 (u1, v1), 2 (u0, v1).
  constexpr int kAround[5] = {0, 1, 3, 2, 0};
  for (int k = 0; k < 4; ++k) {
    const Eigen::Vector3f n = corners[kAround[k]].cross(corners[kAround[k + 1]]);
    cone.side[k] = n.dot(cone.axis) >= 0.0f ? n : Eigen::Vector3f(-n);
  }
  return cone;
}

bool ViewRenderer::outsideTile(const Cone& cone, int primitive) const {
  const Primitive& p = scene_->primitives()[primitive];
  const Eigen::Vector3f to_centre = p.box_centre_local - origin_local_[primitive];
  const float reach_scale = to_centre.norm() + p.box_half_local.norm();
  for (const Eigen::Vector3f& side : cone.side) {
    // The box's farthest point into the side's inner half-space: centre plus |n| . half extents. Outside
    // only with a margin far above the rounding of the per-pixel tests (pixel centres also lie half a
    // pixel inside the tile's edge rays).
    const Eigen::Vector3f n = p.R_local_panel * side;
    const float reach = n.dot(to_centre) + n.cwiseAbs().dot(p.box_half_local);
    if (reach < -1e-4f * n.norm() * reach_scale) return true;
  }
  return false;
}

void ViewRenderer::listCandidates(const Cone& cone) {
  const auto& prims = scene_->primitives();
  const float sin_half = std::sqrt(std::max(0.0f, 1.0f - cone.cos_half_angle * cone.cos_half_angle));
  candidates_.clear();
  for (int i = 0; i < static_cast<int>(prims.size()); ++i) {
    const Eigen::Vector3f to_centre = prims[i].bound_centre_in_panel_m - origin_;
    const float dist = to_centre.norm(), r = prims[i].bound_radius_m;
    // The sphere meets the cone iff angle(axis, centre) <= half angle + asin(r / dist); tile cones are
    // narrow, so the sum stays below pi and the comparison can be made on cosines.
    bool inside = dist <= r;
    if (!inside) {
      const float sin_r = r / dist, cos_r = std::sqrt(1.0f - sin_r * sin_r);
      inside = cone.axis.dot(to_centre) / dist >= cone.cos_half_angle * cos_r - sin_half * sin_r;
    }
    if (!inside || outsideTile(cone, i)) continue;
    // Insertion keeps the list nearest first.
    const Eigen::Matrix3f& R = prims[i].R_local_panel;
    const auto lanes = [](const Eigen::Vector3f& v) { return Float4{v.x(), v.y(), v.z(), 0.0f}; };
    candidates_.push_back({i, near_m_[i], lanes(R * ray_base_), lanes(R * ray_du_), lanes(R * ray_dv_)});
    for (int k = static_cast<int>(candidates_.size()) - 1; k > 0 && candidates_[k - 1].near_m > near_m_[i]; --k)
      std::swap(candidates_[k - 1], candidates_[k]);
  }
}

void ViewRenderer::renderTile(int u0, int v0, int u1, int v1) {
  RowHits row;
  for (int v = v0; v < v1; ++v) {
    intersectRow(v, u0, u1, &row);
    for (int i = 0; i < u1 - u0; i += 4)
      shadePacket(v, u0 + i, std::min(4, u1 - u0 - i), &row.hit[i], &row.d[i], &row.slope[i]);
  }
}

void ViewRenderer::intersectRow(int v, int u0, int u1, RowHits* row) const {
  const auto& prims = scene_->primitives();
  const int w = camera_.width_px;
  const int count = static_cast<int>(candidates_.size());
  LocalHit local;
  float seabed_hint_t = 0.0f;  // the previous pixel's seabed hit: Newton's first guess for this one
  for (int u = u0; u < u1; ++u) {
    SceneHit& hit = row->hit[u - u0];
    const Eigen::Vector3f d = pixelRay(u, v);
    row->d[u - u0] = d;
    row->slope[u - u0] = Eigen::Vector2f::Zero();
    const float inv_len = pixel_rays_[static_cast<std::size_t>(v) * w + u].inv_length;
    float t_best = kMaxRange_m * inv_len;
    hit.primitive = -2;
    const float uf = static_cast<float>(u), vf = static_cast<float>(v);
    for (int k = 0; k < count; ++k) {
      const Candidate& c = candidates_[k];
      if (c.near_m * inv_len >= t_best) break;
      const Float4 d_lanes = c.base + uf * c.du + vf * c.dv;  // as Eigen's sum of the three, per lane
      const Eigen::Vector3f d_local(d_lanes[0], d_lanes[1], d_lanes[2]);
      if (intersectPrimitive(origin_local_[c.primitive], d_local, prims[c.primitive], kTMin, t_best, &local)) {
        t_best = local.t;
        hit.primitive = c.primitive;
        hit.local = local;
      }
    }
    // The seabed lies below its max height: a ray still above it at t_best cannot meet it before.
    float t_seabed = 0.0f;
    if (origin_.z() + t_best * d.z() <= seabed_top_m_ &&
        scene_->seabed().intersectSlope(origin_, d, kTMin, t_best, &t_seabed, &row->slope[u - u0], seabed_hint_t)) {
      t_best = t_seabed;
      hit.primitive = Scene::kSeabed;
    }
    seabed_hint_t = hit.primitive == Scene::kSeabed ? t_best : 0.0f;
    hit.t = hit.primitive != -2 ? t_best : 0.0f;
    depth_m_[static_cast<std::size_t>(v) * w + u] = hit.t;
  }
  // Padding lanes of the last packet: no hit, a benign ray.
  for (int i = u1 - u0; i < ((u1 - u0 + 3) & ~3); ++i) {
    row->hit[i].primitive = -2;
    row->hit[i].t = 0.0f;
    row->d[i] = row->d[0];
    row->slope[i] = Eigen::Vector2f::Zero();
  }
}

namespace {
Float4 toFloat4(const Eigen::Vector4f& v) {
  Float4 r;
  std::memcpy(&r, v.data(), sizeof(r));
  return r;
}
Float4 absFloat4(Float4 x) { return reinterpret_cast<Float4>(reinterpret_cast<Int4>(x) & 0x7FFFFFFF); }
// Lane-wise a . b, summed as Eigen's dot() and squaredNorm() sum three terms: x + (y + z).
Float4 dot3(Float4 ax, Float4 ay, Float4 az, Float4 bx, Float4 by, Float4 bz) { return ax * bx + (ay * by + az * bz); }
}  // namespace

void ViewRenderer::shadePacket(int v, int u, int count, const SceneHit* hit, const Eigen::Vector3f* d,
                               const Eigen::Vector2f* slope) const {
  // pixel_rays_ is padded by 3 entries: the last packet of the image reads within it.
  const PixelRay* ray = &pixel_rays_[static_cast<std::size_t>(v) * camera_.width_px + u];
  // Lanes built from registers (a 16-byte load of 4-byte stores would stall on store forwarding).
  const Float4 t{hit[0].t, hit[1].t, hit[2].t, hit[3].t};
  const Float4 length{ray[0].length, ray[1].length, ray[2].length, ray[3].length};
  const Float4 inv_length{ray[0].inv_length, ray[1].inv_length, ray[2].inv_length, ray[3].inv_length};
  const Float4 dx{d[0].x(), d[1].x(), d[2].x(), d[3].x()}, dy{d[0].y(), d[1].y(), d[2].y(), d[3].y()},
      dz{d[0].z(), d[1].z(), d[2].z(), d[3].z()};
  // Normals: the seabed's from its slope (Seabed::normalOfSlope, lane-wise), the primitives' rotated.
  Eigen::Vector3f n[4];
  for (int i = 0; i < 4; ++i) n[i] = hit[i].primitive >= 0 ? scene_->normalAt(hit[i]) : Eigen::Vector3f::UnitZ();
  const Int4 seabed{-(hit[0].primitive == Scene::kSeabed), -(hit[1].primitive == Scene::kSeabed),
                    -(hit[2].primitive == Scene::kSeabed), -(hit[3].primitive == Scene::kSeabed)};
  const Float4 hx{slope[0].x(), slope[1].x(), slope[2].x(), slope[3].x()};
  const Float4 hy{slope[0].y(), slope[1].y(), slope[2].y(), slope[3].y()};
  const Float4 inv_norm = 1.0f / sqrt4(1.0f + hx * hx + hy * hy);
  const Float4 nx = seabed ? -hx * inv_norm : Float4{n[0].x(), n[1].x(), n[2].x(), n[3].x()};
  const Float4 ny = seabed ? -hy * inv_norm : Float4{n[0].y(), n[1].y(), n[2].y(), n[3].y()};
  const Float4 nz = seabed ? 1.0f * inv_norm : Float4{n[0].z(), n[1].z(), n[2].z(), n[3].z()};
  const Float4 distance = t * length;
  const Float4 px = origin_.x() + t * dx, py = origin_.y() + t * dy, pz = origin_.z() + t * dz;
  // A pixel's footprint at the hit, widened for oblique views: fronto / sqrt(cos), the geometric mean
  // of its two axes (texture level choice only, so the square root is left to the comparison).
  const Float4 fronto_m = t * inv_fx_;
  const Float4 cos_raw = absFloat4(dot3(nx, ny, nz, dx, dy, dz)) * inv_length;
  const Float4 cos_view = cos_raw < 0.1f ? Float4{} + 0.1f : cos_raw;
  const Float4 footprint2 = fronto_m * fronto_m / cos_view;
  // I cos(theta_s) cos(phi) / d_l^2 per lamp, with both cosines = dot / d_l; one division for both
  // lamps (1 / (q0 q1) times the other's q).
  Float4 n_l[2], axis_l[2], dl2[2];
  const Eigen::Vector3f& a = lamps_.axis_in_panel;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3f& lamp = lamps_.p_lamp_in_panel_m[k];
    const Float4 lx = lamp.x() - px, ly = lamp.y() - py, lz = lamp.z() - pz;
    n_l[k] = dot3(nx, ny, nz, lx, ly, lz);
    axis_l[k] = -dot3(Float4{} + a.x(), Float4{} + a.y(), Float4{} + a.z(), lx, ly, lz);
    dl2[k] = dot3(lx, ly, lz, lx, ly, lz);
  }
  const Float4 q0 = dl2[0] * dl2[0], q1 = dl2[1] * dl2[1];
  const Float4 inv_q01 = 1.0f / (q0 * q1);
  const Float4 irradiance[2] = {optics_.lamp_intensity * n_l[0] * axis_l[0] * (q1 * inv_q01),
                                optics_.lamp_intensity * n_l[1] * axis_l[1] * (q0 * inv_q01)};
  // A lamp behind the surface or the beam contributes nothing: its irradiance is 0 (adding 0 t leaves
  // the sum's bits as skipping it would).
  Float4 lit[2] = {n_l[0] <= 0.0f || axis_l[0] <= 0.0f ? Float4{} : irradiance[0],
                   n_l[1] <= 0.0f || axis_l[1] <= 0.0f ? Float4{} : irradiance[1]};
  const Float4 dl[2] = {sqrt4(dl2[0]), sqrt4(dl2[1])};
  if (effects_.beam.cut_off) {  // the beam's edge: axis_l / d_l is cos(phi)
    lit[0] *= effects_.beam.cut(axis_l[0] / dl[0]);
    lit[1] *= effects_.beam.cut(axis_l[1] / dl[1]);
  }
  const WaterPath::Place4 lamp_path[2] = {water_.locate4(dl[0] + distance), water_.locate4(dl[1] + distance)};
  const WaterPath::Place4 view_path = water_.locate4(distance);
  Eigen::Vector4f albedo[4];
  scene_->albedo4(hit, origin_, d, px, py, footprint2, albedo);
  float* out = radiance_ + (static_cast<std::size_t>(v) * camera_.width_px + u) * channels_;
  if (deep_sea_) {
    const bool column = effects_.column();
    const Float4 position = column ? column_.samplePosition4(distance) : Float4{};
    for (int i = 0; i < count; ++i, out += channels_) {
      const bool surface = hit[i].primitive != -2;
      Float4 E{}, view = Float4{} + 1.0f;
      if (surface) {
        E = toFloat4(lit[0][i] * water_.interpolate(lamp_path[0].row[i], lamp_path[0].fraction[i]) +
                     lit[1][i] * water_.interpolate(lamp_path[1].row[i], lamp_path[1].fraction[i]));
        view = toFloat4(water_.interpolate(view_path.row[i], view_path.fraction[i]));
      }
      // Lanes 0-2 the lamps' backscatter up to the hit (or over the whole range in open water), lane 3 the
      // plumes' transmittance there (1 without plumes).
      const Float4 col = column ? column_.at(u + i, v, surface ? position[i] : WaterColumn::kLastPosition)
                                : Float4{0.0f, 0.0f, 0.0f, 1.0f};
      const float cos2 = inv_length[i] * inv_length[i];
      shadeDeepSea(v, u + i, surface, distance[i], col, toFloat4(albedo[i]), E, view, cos2 * cos2, out);
    }
    return;
  }
  for (int i = 0; i < count; ++i, out += channels_) {
    Eigen::Vector4f L = backscatter_;
    if (hit[i].primitive != -2) {
      Eigen::Vector4f E = Eigen::Vector4f::Zero();
      E += lit[0][i] * water_.interpolate(lamp_path[0].row[i], lamp_path[0].fraction[i]);
      E += lit[1][i] * water_.interpolate(lamp_path[1].row[i], lamp_path[1].fraction[i]);
      const Eigen::Vector4f veil =
          Eigen::Vector4f::Ones() - water_.interpolate(view_path.row[i], view_path.fraction[i]);
      L = albedo[i].cwiseProduct(E) + backscatter_.cwiseProduct(veil);
    }
    const float cos2 = inv_length[i] * inv_length[i];
    L *= cos2 * cos2;  // cos^4 of the angle off the optical axis
    if (channels_ == 3) {
      out[0] = L[0], out[1] = L[1], out[2] = L[2];
    } else {
      out[0] = 0.114f * L[0] + 0.587f * L[1] + 0.299f * L[2];
    }
  }
}

inline void ViewRenderer::shadeDeepSea(int v, int u, bool surface, float distance_m, Float4 column, Float4 albedo, Float4 E,
                                Float4 transmittance, float cos4, float* out) const {
  // All in registers (Float4): building a vector from lanes stored one by one would stall on store
  // forwarding.
  const float plume_t = column[3];
  Float4 direct{};
  Float4 veil = backscatter4_;
  if (surface) {
    // The lamp's path through the plumes taken as the view path's (water_column.h): T_p^2.
    direct = albedo * E * (plume_t * plume_t);
    veil = backscatter4_ * (1.0f - plume_t * transmittance);
  }
  if (effects_.lamp_backscatter) veil = column * Float4{1.0f, 1.0f, 1.0f, 0.0f};
  direct *= cos4;
  const Float4 L = direct + veil * cos4;
  const std::size_t pixel = static_cast<std::size_t>(v) * camera_.width_px + u;
  const bool blur = effects_.forward_scatter_rad_per_m > 0.0f;
  if (blur) distance_out_[pixel] = surface ? distance_m : 0.0f;
  float* direct_out = blur ? direct_out_ + pixel * channels_ : nullptr;
  if (channels_ == 3) {
    out[0] = L[0], out[1] = L[1], out[2] = L[2];
    if (direct_out) direct_out[0] = direct[0], direct_out[1] = direct[1], direct_out[2] = direct[2];
  } else {
    out[0] = 0.114f * L[0] + 0.587f * L[1] + 0.299f * L[2];
    if (direct_out) direct_out[0] = 0.114f * direct[0] + 0.587f * direct[1] + 0.299f * direct[2];
  }
}

}  // namespace deepnav::sim
