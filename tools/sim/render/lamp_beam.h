#pragma once
#include <cmath>
#include <numbers>

#include "tools/sim/render/float4.h"

namespace deepnav::sim {

// The lamps' beam pattern beyond the renderer's cosine beam: cos(phi) (phi off the lamp's axis) times a
// cut-off that falls smoothly from 1 at 0.75 of the half angle to 0 at the half angle (the reflector's
// edge). A half angle of 90 deg or more is the plain cosine beam (cut() is then never called).
struct LampBeam {
  bool cut_off = false;
  float cos_edge = 0.0f;  // cos(half angle): the pattern is 0 beyond
  float inv_span = 1.0f;  // 1 / (cos(0.75 half angle) - cos(half angle))

  static LampBeam fromHalfAngle(double half_angle_deg) {
    LampBeam b;
    if (half_angle_deg >= 90.0) return b;
    const double half_rad = half_angle_deg * std::numbers::pi / 180.0;
    b.cut_off = true;
    b.cos_edge = static_cast<float>(std::cos(half_rad));
    b.inv_span = static_cast<float>(1.0 / (std::cos(0.75 * half_rad) - std::cos(half_rad)));
    return b;
  }
  // The cut-off factor for cos(phi) per lane: smoothstep, 0 outside the cone, 1 inside its core.
  Float4 cut(Float4 cos_phi) const {
    Float4 x = (cos_phi - cos_edge) * inv_span;
    x = x < 0.0f ? Float4{} : x;
    x = x > 1.0f ? Float4{} + 1.0f : x;
    return x * x * (3.0f - 2.0f * x);
  }
  // The whole pattern (cosine times cut-off, 0 behind the lamp) for cos(phi) per lane.
  Float4 pattern(Float4 cos_phi) const {
    const Float4 front = cos_phi < 0.0f ? Float4{} : cos_phi;
    return cut_off ? front * cut(cos_phi) : front;
  }
};

// Henyey-Greenstein phase function per steradian, p(cos theta) = (1 - g^2) / (4 pi (1 + g^2 - 2 g cos)^1.5),
// theta the scattering angle (0 = straight on). g = 0.924 gives b_b / b = 0.017, close to Petzold's
// turbid-water measurements (0.018-0.019; Mobley, Light and Water, 1994, ch. 3).
struct HenyeyGreenstein {
  float g = 0.924f;
  Float4 operator()(Float4 cos_theta) const {
    const Float4 q = (1.0f + g * g) - (2.0f * g) * cos_theta;
    return ((1.0f - g * g) / (4.0f * std::numbers::pi_v<float>)) / (q * sqrt4(q));
  }
};

}  // namespace deepnav::sim
