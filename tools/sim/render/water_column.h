#pragma once
#include <array>
#include <vector>

#include <Eigen/Core>

#include "tools/sim/render/float4.h"
#include "tools/sim/render/sediment_plume.h"
#include "tools/sim/render/water_optics.h"

namespace deepnav::sim {

// The water column along one view's pixel rays, per frame: the lamps' light scattered once towards the
// camera (lamp backscatter) and the transmittance of the sediment plumes, both as running integrals of
// the distance s along the ray from the camera:
//   L_bs,c(s) = int_0^s b_c(x) p(cos theta) pi I B(phi) / r^2 exp(-beta_c (r + s')) T_p(s')^2 ds'
//   T_p(s)    = exp(-int_0^s dc(x) ds')
// x = o + s' d the point on the ray, r its distance to the lamp, phi its angle off the lamp's axis, B the
// beam pattern (lamp_beam.h), theta the scattering angle between the lamp's light and the direction back
// to the camera, p the Henyey-Greenstein phase function, b_c = albedo (beta_c + dc(x)) the scattering
// coefficient with the plumes' extra attenuation dc (sediment_plume.h), summed over both lamps (pi I: the
// lamp's radiant intensity in the units where I is the radiance of a white Lambertian surface 1 m in
// front of it). The plume transmittance of the lamp's path is taken as that of the view path (the lamps
// are 0.3 m from the camera against plume scales of metres): T_p^2 for the round trip.
//
// Both are smooth in the ray's direction (beam edges are soft, plumes metres wide), so they are integrated
// on a grid of rays every kStep_px pixels (pixel centres (32 i, 32 j)), at kSamples distances
// s_k = kRange_m (k / (kSamples - 1))^2 (dense near the camera, where the lamps' light is strong), by the
// trapezoid rule, and looked up per pixel bilinearly in (u, v) and linearly in the sample position. Light
// scattered beyond kRange_m is left out: with the 1 / s^2 fall-off of the lamps' light alone (no
// attenuation, beams overlapping the ray from 0.3 m on) that is 0.3 / 20 = 1.5 % of the total, less in
// any of the presets' water. Lanes 0-2: L_bs (B, G, R); lane 3: T_p.
class WaterColumn {
 public:
  static constexpr int kStep_px = 32;
  static constexpr int kSamples = 128;
  static constexpr float kRange_m = 20.0f;

  void init(int width_px, int height_px, const WaterOptics& optics, const WaterEffects& effects,
            const SedimentPlumes* plumes);
  // The rays of the frame: d(u, v) = ray_base + u ray_du + v ray_dv from origin (panel frame), and the
  // lamps (positions, common axis).
  void prepare(const Eigen::Vector3f& origin, const Eigen::Vector3f& ray_base, const Eigen::Vector3f& ray_du,
               const Eigen::Vector3f& ray_dv, const std::array<Eigen::Vector3f, 2>& lamps_in_panel_m,
               const Eigen::Vector3f& lamp_axis_in_panel);
  // Where distances (m, per lane) fall among the samples: continuous sample positions.
  Float4 samplePosition4(Float4 distance_m) const {
    Float4 q = sqrt4(distance_m * (1.0f / kRange_m)) * static_cast<float>(kSamples - 1);
    q = q < 0.0f ? Float4{} : q;
    return q > kLastPosition ? Float4{} + kLastPosition : q;
  }
  // The column of pixel (u, v) up to sample position `position` (kLastPosition: the whole range).
  Float4 at(int u, int v, float position) const {
    const int k = static_cast<int>(position);
    const float f = position - static_cast<float>(k);
    const unsigned uu = static_cast<unsigned>(u), vv = static_cast<unsigned>(v);
    const float wu = static_cast<float>(uu % kStep_px) * (1.0f / kStep_px);
    const float wv = static_cast<float>(vv % kStep_px) * (1.0f / kStep_px);
    const Float4* p = table_.data() + (static_cast<std::size_t>(vv / kStep_px) * nodes_u_ + uu / kStep_px) * kSamples + k;
    const std::size_t down = static_cast<std::size_t>(nodes_u_) * kSamples;
    // Along the samples first (4 lerps), then across the grid (3).
    const Float4 a = p[0] + f * (p[1] - p[0]), b = p[kSamples] + f * (p[kSamples + 1] - p[kSamples]);
    const Float4 c = p[down] + f * (p[down + 1] - p[down]);
    const Float4 d = p[down + kSamples] + f * (p[down + kSamples + 1] - p[down + kSamples]);
    const Float4 top = a + wu * (b - a), bottom = c + wu * (d - c);
    return top + wv * (bottom - top);
  }
  static constexpr float kLastPosition = static_cast<float>(kSamples - 1) - 1e-3f;

 private:
  void integrateRay(const Eigen::Vector3f& origin, const Eigen::Vector3f& d_unit, Float4* out) const;

  WaterEffects effects_;
  std::array<float, 3> beta_per_m_{};
  float lamp_intensity_ = 1.0f;
  const SedimentPlumes* plumes_ = nullptr;
  int nodes_u_ = 0, nodes_v_ = 0;
  std::array<Float4, kSamples / 4> s_m_{};  // the sample distances, four per vector
  std::vector<Float4> table_;               // [node v][node u][sample]
  // Per frame.
  std::array<Eigen::Vector3f, 2> lamps_{};
  Eigen::Vector3f axis_ = Eigen::Vector3f::UnitX();
};

}  // namespace deepnav::sim
