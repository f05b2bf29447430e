#include "tools/sim/render/sediment_plume.h"

#include <algorithm>
#include <cmath>

#include "tools/sim/render/float4_exp.h"

namespace deepnav::sim {

void SedimentPlumes::init(const std::vector<SedimentPlumeConfig>& plumes, const Eigen::Isometry3d& T_odom_panel,
                          const std::array<double, 3>& current_in_odom_mps) {
  plumes_.clear();
  const Eigen::Isometry3d T_panel_odom = T_odom_panel.inverse();
  for (const SedimentPlumeConfig& c : plumes) {
    // On the seabed: z of the panel's footprint (the relief's +-5 cm are below the plume's scale).
    const Eigen::Vector3d centre_odom(c.centre_in_odom_m[0], c.centre_in_odom_m[1], T_odom_panel.translation().z());
    plumes_.push_back({c, (T_panel_odom * centre_odom).head<2>().cast<float>()});
  }
  const Eigen::Vector3d current(current_in_odom_mps[0], current_in_odom_mps[1], current_in_odom_mps[2]);
  current_in_panel_mps_ = (T_panel_odom.linear() * current).head<2>().cast<float>();
  active_.reserve(plumes_.size());
}

void SedimentPlumes::setTime(double t_s) {
  active_.clear();
  for (const Plume& p : plumes_) {
    const double age_s = t_s - p.config.t_start_s;
    if (age_s <= 0.0) continue;
    const double k = 1.0 + p.config.growth_mps * age_s / p.config.radius_m;
    const double x = std::min(1.0, age_s / p.config.rise_s);
    const double ramp = x * x * (3.0 - 2.0 * x);
    const double peak = p.config.attenuation_per_m * ramp * std::exp(-age_s / p.config.decay_s) / (k * k * k);
    const double sh = p.config.radius_m * k, sv = p.config.height_m * k;
    const Eigen::Vector2f centre = p.centre_in_panel_m + static_cast<float>(age_s) * current_in_panel_mps_;
    active_.push_back({centre.x(), centre.y(), static_cast<float>(0.5 / (sh * sh)), static_cast<float>(0.5 / (sv * sv)),
                       static_cast<float>(peak)});
  }
}

Float4 SedimentPlumes::attenuation4(Float4 x, Float4 y, Float4 z) const {
  Float4 sum{};
  for (const Active& a : active_) {
    const Float4 dx = x - a.cx, dy = y - a.cy;
    sum += a.peak_per_m * exp4(-(dx * dx + dy * dy) * a.inv_2sh2 - z * z * a.inv_2sv2);
  }
  return sum;
}

float SedimentPlumes::attenuationAt(const Eigen::Vector3f& p) const {
  return attenuation4(Float4{} + p.x(), Float4{} + p.y(), Float4{} + p.z())[0];
}

}  // namespace deepnav::sim
