#pragma once
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tools/sim/render/float4.h"
#include "tools/sim/water_config.h"

namespace deepnav::sim {

// Sediment plumes raised from the seabed (scenario key water.plumes): each an anisotropic Gaussian cloud
// of extra beam attenuation centred on the seabed (z = 0 in the panel frame P),
//   dc(x, t) = c(t) exp(-((x - m(t))^2 + (y - m_y(t))^2) / (2 s_h(t)^2) - z^2 / (2 s_v(t)^2)),
// with k(t) = 1 + growth (t - t0) / radius the spreading, s_h = radius k, s_v = height k,
// c(t) = attenuation ramp(t) exp(-(t - t0) / decay) / k^3 (the raised mass spread over the growing volume
// and settling out; ramp rises smoothly from 0 to 1 over rise_s), m(t) drifting with the horizontal
// current. Zero before t0. The renderer adds dc to the beam attenuation along each ray and counts it as
// scattering with the water's single-scattering albedo (water_column.h).
class SedimentPlumes {
 public:
  // T_odom_panel takes the plume centres (on the seabed, at the panel footprint's height) and the current
  // into P.
  void init(const std::vector<SedimentPlumeConfig>& plumes, const Eigen::Isometry3d& T_odom_panel,
            const std::array<double, 3>& current_in_odom_mps);
  bool empty() const { return plumes_.empty(); }
  // The state of every plume at time t (s of the dive).
  void setTime(double t_s);
  // Extra beam attenuation (1/m) at four points (lanes) at the current time.
  Float4 attenuation4(Float4 x, Float4 y, Float4 z) const;
  // The same at one point.
  float attenuationAt(const Eigen::Vector3f& p_in_panel_m) const;

 private:
  struct Plume {
    SedimentPlumeConfig config;
    Eigen::Vector2f centre_in_panel_m;  // at t0
  };
  struct Active {  // per frame
    float cx, cy, inv_2sh2, inv_2sv2, peak_per_m;
  };
  std::vector<Plume> plumes_;
  std::vector<Active> active_;
  Eigen::Vector2f current_in_panel_mps_ = Eigen::Vector2f::Zero();
};

}  // namespace deepnav::sim
