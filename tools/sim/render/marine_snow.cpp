#include "tools/sim/render/marine_snow.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

namespace {
constexpr float kNearest_m = 0.05f;
constexpr float kFade_m = 0.5f;
constexpr std::uint64_t kSnowStream = 0x5A0F1A4Eu;
}  // namespace

void MarineSnow::init(const WaterConfig& water, const Eigen::Isometry3d& T_odom_panel, std::uint64_t seed) {
  for (auto* v : {&x0_, &y0_, &z0_, &sink_mps_, &diameter_m_}) v->clear();
  lit_.clear();
  albedo_ = static_cast<float>(water.snow_albedo);
  const double volume_m3 = static_cast<double>(kCube_m) * kCube_m * kCube_m;
  const auto count = static_cast<std::size_t>(std::llround(water.snow_density_per_m3 * volume_m3));
  if (count == 0) return;
  const Eigen::Matrix3d R_panel_odom = T_odom_panel.linear().transpose();
  current_in_panel_mps_ =
      R_panel_odom * Eigen::Vector3d(water.current_mps[0], water.current_mps[1], water.current_mps[2]);
  // Sinking is along odom's down, which is P's down (P is only yawed).
  NormalRng rng(NormalRng::subSeed(seed, kSnowStream));
  const double log_d0 = std::log(water.snow_diameter_mm[0] * 1e-3), log_d1 = std::log(water.snow_diameter_mm[1] * 1e-3);
  for (auto* v : {&x0_, &y0_, &z0_, &sink_mps_, &diameter_m_}) v->reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    x0_.push_back(static_cast<float>(kCube_m * rng.uniform()));
    y0_.push_back(static_cast<float>(kCube_m * rng.uniform()));
    z0_.push_back(static_cast<float>(kCube_m * rng.uniform()));
    sink_mps_.push_back(static_cast<float>(water.snow_sink_mps * (0.5 + rng.uniform())));
    diameter_m_.push_back(static_cast<float>(std::exp(log_d0 + (log_d1 - log_d0) * rng.uniform())));
  }
  lit_.reserve(count);
}

void MarineSnow::update(double t_s, const Eigen::Vector3f& p_rig, const Eigen::Vector3f& ahead,
                        const std::array<Eigen::Vector3f, 2>& lamps, const Eigen::Vector3f& lamp_axis,
                        const WaterOptics& optics, const LampBeam& beam) {
  lit_.clear();
  const Eigen::Vector3f corner = p_rig + kAhead_m * ahead - Eigen::Vector3f::Constant(0.5f * kCube_m);
  // The current's displacement, the same for every particle, wrapped in double (over a long dive it
  // exceeds float's resolution of the cube); the sinking (under 1 mm/s) stays small enough for float.
  Eigen::Vector3f shift;
  for (int k = 0; k < 3; ++k)
    shift[k] = static_cast<float>(std::fmod(current_in_panel_mps_[k] * t_s, static_cast<double>(kCube_m))) - corner[k];
  const float t = static_cast<float>(t_s);
  const float inv_l = 1.0f / kCube_m;
  const float reach2 = (kRange_m + 0.5f) * (kRange_m + 0.5f);
  const float intensity = optics.lamp_intensity;
  // q to [0, L): floor by truncation and a correction below zero (no call to floorf, vectorisable).
  const auto wrap = [inv_l](float q) {
    const float x = q * inv_l;
    const int n = static_cast<int>(x);
    return q - kCube_m * static_cast<float>(n - (static_cast<float>(n) > x));
  };
  for (std::size_t i = 0; i < x0_.size(); ++i) {
    const Eigen::Vector3f p = corner + Eigen::Vector3f(wrap(x0_[i] + shift.x()), wrap(y0_[i] + shift.y()),
                                                       wrap(z0_[i] + shift.z() - sink_mps_[i] * t));
    const Eigen::Vector3f from_rig = p - p_rig;
    if (from_rig.squaredNorm() > reach2 || from_rig.dot(ahead) < kNearest_m) continue;
    std::array<float, 3> radiance{};
    bool any = false;
    for (const Eigen::Vector3f& lamp : lamps) {
      const Eigen::Vector3f l = p - lamp;
      const float r2 = l.squaredNorm(), r = std::sqrt(r2);
      const float b = beam.pattern(Float4{} + lamp_axis.dot(l) / r)[0];
      if (b <= 0.0f) continue;
      any = true;
      for (int c = 0; c < 3; ++c)
        radiance[c] += albedo_ * intensity * b / r2 * std::exp(-optics.attenuation_per_m[c] * r);
    }
    if (any) lit_.push_back({p, diameter_m_[i], radiance});
  }
}

void MarineSnow::draw(const Eigen::Matrix3f& R_panel_cam, const Eigen::Vector3f& p_cam, const CameraConfig& camera,
                      const WaterOptics& optics, int channels, float* radiance, const float* depth_m) const {
  const Eigen::Matrix3f R_cam_panel = R_panel_cam.transpose();
  const float fx = static_cast<float>(camera.fx_px), fy = static_cast<float>(camera.fy_px);
  const float cx = static_cast<float>(camera.cx_px), cy = static_cast<float>(camera.cy_px);
  for (const Lit& s : lit_) {
    const Eigen::Vector3f q = R_cam_panel * (s.p_in_panel_m - p_cam);
    if (q.z() < kNearest_m) continue;
    const float distance = q.norm();
    if (distance > kRange_m) continue;
    const float inv_z = 1.0f / q.z();
    const float u = cx + fx * q.x() * inv_z, v = cy + fy * q.y() * inv_z;
    const float radius_px = 0.5f * fx * s.diameter_m * inv_z;
    if (u < -radius_px - 1.0f || v < -radius_px - 1.0f || u > camera.width_px + radius_px ||
        v > camera.height_px + radius_px)
      continue;
    const float fade = std::min(1.0f, (kRange_m - distance) / kFade_m);
    float colour[3];
    for (int c = 0; c < 3; ++c) colour[c] = s.radiance[c] * std::exp(-optics.attenuation_per_m[c] * distance);
    // The pixel's cos^4 vignetting, as the shading applies it.
    const float cos2 = q.z() * q.z() / (distance * distance);
    for (float& c : colour) c *= cos2 * cos2;
    if (channels == 1) colour[0] = 0.114f * colour[0] + 0.587f * colour[1] + 0.299f * colour[2];
    const float area_px = fade * std::numbers::pi_v<float> * radius_px * radius_px;
    splat(u, v, area_px, radius_px, colour, q.z(), channels, camera, radiance, depth_m);
  }
}

void MarineSnow::splat(float u, float v, float area_px, float radius_px, const float* colour, float depth, int channels,
                       const CameraConfig& camera, float* radiance, const float* depth_m) const {
  const int w = camera.width_px, h = camera.height_px;
  const auto blend = [&](int x, int y, float alpha) {
    if (x < 0 || y < 0 || x >= w || y >= h || alpha <= 0.0f) return;
    const std::size_t i = static_cast<std::size_t>(y) * w + x;
    const float behind = depth_m[i];
    if (behind > 0.0f && behind < depth) return;  // hidden by a surface
    alpha = std::min(alpha, 1.0f);
    float* out = radiance + i * channels;
    for (int c = 0; c < channels; ++c) out[c] += alpha * (colour[c] - out[c]);
  };
  if (radius_px < 0.75f) {
    const int x0 = static_cast<int>(std::floor(u)), y0 = static_cast<int>(std::floor(v));
    const float fx = u - static_cast<float>(x0), fy = v - static_cast<float>(y0);
    blend(x0, y0, area_px * (1.0f - fx) * (1.0f - fy));
    blend(x0 + 1, y0, area_px * fx * (1.0f - fy));
    blend(x0, y0 + 1, area_px * (1.0f - fx) * fy);
    blend(x0 + 1, y0 + 1, area_px * fx * fy);
    return;
  }
  const float fade = area_px / (std::numbers::pi_v<float> * radius_px * radius_px);
  const int x0 = static_cast<int>(std::floor(u - radius_px - 0.5f)), x1 = static_cast<int>(std::ceil(u + radius_px + 0.5f));
  const int y0 = static_cast<int>(std::floor(v - radius_px - 0.5f)), y1 = static_cast<int>(std::ceil(v + radius_px + 0.5f));
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      const float dx = static_cast<float>(x) - u, dy = static_cast<float>(y) - v;
      const float coverage = std::clamp(radius_px + 0.5f - std::sqrt(dx * dx + dy * dy), 0.0f, 1.0f);
      blend(x, y, fade * coverage);
    }
  }
}

}  // namespace deepnav::sim
