#include "tools/sim/render/water_column.h"

#include <numbers>

#include "tools/sim/render/float4_exp.h"

namespace deepnav::sim {

void WaterColumn::init(int width_px, int height_px, const WaterOptics& optics, const WaterEffects& effects,
                       const SedimentPlumes* plumes) {
  effects_ = effects;
  beta_per_m_ = optics.attenuation_per_m;
  lamp_intensity_ = optics.lamp_intensity;
  plumes_ = plumes != nullptr && !plumes->empty() ? plumes : nullptr;
  // Nodes up to the first multiple of the step at or beyond the last pixel, plus one: every pixel has a
  // node on each side.
  nodes_u_ = (width_px - 1) / kStep_px + 2;
  nodes_v_ = (height_px - 1) / kStep_px + 2;
  table_.assign(static_cast<std::size_t>(nodes_u_) * nodes_v_ * kSamples, Float4{});
  for (int k = 0; k < kSamples; ++k) {
    const float x = static_cast<float>(k) / static_cast<float>(kSamples - 1);
    s_m_[k / 4][k % 4] = kRange_m * x * x;
  }
}

void WaterColumn::prepare(const Eigen::Vector3f& origin, const Eigen::Vector3f& ray_base,
                          const Eigen::Vector3f& ray_du, const Eigen::Vector3f& ray_dv,
                          const std::array<Eigen::Vector3f, 2>& lamps_in_panel_m,
                          const Eigen::Vector3f& lamp_axis_in_panel) {
  lamps_ = lamps_in_panel_m;
  axis_ = lamp_axis_in_panel;
  for (int j = 0; j < nodes_v_; ++j) {
    for (int i = 0; i < nodes_u_; ++i) {
      const Eigen::Vector3f d = ray_base + static_cast<float>(kStep_px * i) * ray_du + static_cast<float>(kStep_px * j) * ray_dv;
      integrateRay(origin, d.normalized(), table_.data() + (static_cast<std::size_t>(j) * nodes_u_ + i) * kSamples);
    }
  }
}

void WaterColumn::integrateRay(const Eigen::Vector3f& o, const Eigen::Vector3f& d, Float4* out) const {
  constexpr int kGroups = kSamples / 4;
  // The plumes' extra attenuation at the samples, its running integral (trapezoids) and transmittance.
  std::array<Float4, kGroups> dc{}, plume_t{};
  for (Float4& t : plume_t) t = Float4{} + 1.0f;
  if (plumes_ != nullptr) {
    for (int g = 0; g < kGroups; ++g)
      dc[g] = plumes_->attenuation4(o.x() + s_m_[g] * d.x(), o.y() + s_m_[g] * d.y(), o.z() + s_m_[g] * d.z());
    float tau = 0.0f;
    std::array<Float4, kGroups> tau_k{};
    for (int k = 1; k < kSamples; ++k) {
      const float ds = s_m_[k / 4][k % 4] - s_m_[(k - 1) / 4][(k - 1) % 4];
      tau += 0.5f * ds * (dc[k / 4][k % 4] + dc[(k - 1) / 4][(k - 1) % 4]);
      tau_k[k / 4][k % 4] = tau;
    }
    for (int g = 0; g < kGroups; ++g) plume_t[g] = exp4(-tau_k[g]);
  }
  // The in-scattered radiance per unit length at the samples, per channel.
  std::array<std::array<Float4, kGroups>, 3> f{};
  if (effects_.lamp_backscatter) {
    const float pi_i = std::numbers::pi_v<float> * lamp_intensity_;
    for (int g = 0; g < kGroups; ++g) {
      const Float4 s = s_m_[g];
      const Float4 x = o.x() + s * d.x(), y = o.y() + s * d.y(), z = o.z() + s * d.z();
      std::array<Float4, 3> sum{};
      for (const Eigen::Vector3f& lamp : lamps_) {
        const Float4 lx = x - lamp.x(), ly = y - lamp.y(), lz = z - lamp.z();  // lamp to point
        const Float4 r2 = lx * lx + ly * ly + lz * lz;
        const Float4 r = sqrt4(r2);
        const Float4 inv_r = 1.0f / r;
        const Float4 cos_phi = (axis_.x() * lx + axis_.y() * ly + axis_.z() * lz) * inv_r;
        // Light travelling along l / r, scattered back along -d.
        const Float4 cos_theta = -(lx * d.x() + ly * d.y() + lz * d.z()) * inv_r;
        const Float4 geometry = pi_i * effects_.beam.pattern(cos_phi) * effects_.phase(cos_theta) * inv_r * inv_r;
        for (int c = 0; c < 3; ++c) sum[c] += geometry * exp4(-beta_per_m_[c] * (r + s));
      }
      const Float4 round_trip = plume_t[g] * plume_t[g];
      for (int c = 0; c < 3; ++c)
        f[c][g] = effects_.scattering_albedo * (beta_per_m_[c] + dc[g]) * sum[c] * round_trip;
    }
  }
  float running[3] = {0.0f, 0.0f, 0.0f};
  out[0] = Float4{0.0f, 0.0f, 0.0f, 1.0f};
  for (int k = 1; k < kSamples; ++k) {
    const int g = k / 4, l = k % 4, gp = (k - 1) / 4, lp = (k - 1) % 4;
    const float ds = s_m_[g][l] - s_m_[gp][lp];
    for (int c = 0; c < 3; ++c) running[c] += 0.5f * ds * (f[c][g][l] + f[c][gp][lp]);
    out[k] = Float4{running[0], running[1], running[2], plume_t[g][l]};
  }
}

}  // namespace deepnav::sim
