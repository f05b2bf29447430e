#include "tools/sim/sensors/imu_vibration.h"

#include <cmath>
#include <numbers>

namespace deepnav::sim {

void ImuVibration::init(double rms, const std::array<double, kTones>& frequencies_hz, NormalRng* rng) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  for (int j = 0; j < kTones; ++j) omega_radps_[j] = kTwoPi * frequencies_hz[j];
  for (auto& axis : phase_rad_)
    for (double& phase : axis) phase = kTwoPi * rng->uniform();
  amplitude_ = rms * std::sqrt(2.0 * kTonalPowerFraction / kTones);
  broadband_sigma_ = rms * std::sqrt(1.0 - kTonalPowerFraction);
}

Eigen::Vector3d ImuVibration::sample(TimeUs t_us, NormalRng* rng) const {
  // Time from the integer stamp: the tone's phase stays exact over long dives.
  const double t_s = static_cast<double>(t_us) * 1e-6;
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) {
    double tonal = 0.0;
    for (int j = 0; j < kTones; ++j) tonal += std::sin(omega_radps_[j] * t_s + phase_rad_[i][j]);
    v[i] = amplitude_ * tonal + rng->normal(broadband_sigma_);
  }
  return v;
}

}  // namespace deepnav::sim
