#include "tools/sim/render/fish_school.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

void FishSchool::init(int count, double panel_half_width_m, double standoff_m, std::uint64_t seed) {
  NormalRng rng(NormalRng::subSeed(seed, 0xF15Bu));
  const double r_min = panel_half_width_m + 0.35;
  const double r_max = std::max(r_min, panel_half_width_m + standoff_m - 0.25);
  fish_.clear();
  for (int i = 0; i < count; ++i) {
    Fish f;
    f.path_radius_m = static_cast<float>(r_min + (r_max - r_min) * rng.uniform());
    f.z_m = static_cast<float>(0.35 + 1.3 * rng.uniform());
    const double speed_mps = 0.15 + 0.25 * rng.uniform();
    f.omega_radps = static_cast<float>((rng.uniform() < 0.5 ? -1.0 : 1.0) * speed_mps / f.path_radius_m);
    f.phase_rad = static_cast<float>(2.0 * std::numbers::pi * rng.uniform());
    f.bob_amplitude_m = static_cast<float>(0.02 + 0.06 * rng.uniform());
    f.bob_omega_radps = static_cast<float>(0.4 + 0.8 * rng.uniform());
    const float length = static_cast<float>(0.08 + 0.06 * rng.uniform());
    f.semi_axes_m = Eigen::Vector3f(length, 0.22f * length, 0.32f * length);
    fish_.push_back(f);
  }
}

Eigen::Vector3f FishSchool::positionAt(const Fish& f, double t_s) const {
  const double theta = f.phase_rad + f.omega_radps * t_s;
  const double c = std::cos(theta), s = std::sin(theta);
  const double rho = f.path_radius_m * std::pow(c * c * c * c + s * s * s * s, -0.25);
  const double z = f.z_m + f.bob_amplitude_m * std::sin(f.bob_omega_radps * t_s + f.phase_rad);
  return Eigen::Vector3f(static_cast<float>(rho * c), static_cast<float>(rho * s), static_cast<float>(z));
}

void FishSchool::poseAt(int i, double t_s, Eigen::Matrix3f* R_panel_fish, Eigen::Vector3f* p_fish_in_panel_m) const {
  const Fish& f = fish_[i];
  constexpr double kDt_s = 0.05;
  *p_fish_in_panel_m = positionAt(f, t_s);
  Eigen::Vector3f heading = positionAt(f, t_s + kDt_s) - positionAt(f, t_s - kDt_s);
  heading.z() *= 0.5f;  // fish keep fairly level while bobbing
  const Eigen::Vector3f x = heading.normalized();
  const Eigen::Vector3f y = Eigen::Vector3f::UnitZ().cross(x).normalized();
  R_panel_fish->col(0) = x;
  R_panel_fish->col(1) = y;
  R_panel_fish->col(2) = x.cross(y);
}

}  // namespace deepnav::sim
