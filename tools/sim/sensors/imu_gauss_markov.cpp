#include "tools/sim/sensors/imu_gauss_markov.h"

#include <cmath>

namespace deepnav::sim {

double gaussMarkovAllanDeviation(double sigma, double correlation_time_s, double tau_s) {
  const double x = tau_s / correlation_time_s;
  const double bracket = 2.0 * x - 3.0 + 4.0 * std::exp(-x) - std::exp(-2.0 * x);
  return sigma * std::sqrt(bracket) / x;
}

void GaussMarkov3::init(double sigma, double correlation_time_s, double dt_s, NormalRng* rng) {
  decay_ = std::exp(-dt_s / correlation_time_s);
  drive_sigma_ = sigma * std::sqrt(1.0 - decay_ * decay_);  // keeps the variance at sigma^2
  // Explicit order of draws (x, y, z).
  const double x = rng->normal(sigma);
  const double y = rng->normal(sigma);
  const double z = rng->normal(sigma);
  value_ = {x, y, z};
}

void GaussMarkov3::step(NormalRng* rng) {
  const double x = rng->normal(drive_sigma_);
  const double y = rng->normal(drive_sigma_);
  const double z = rng->normal(drive_sigma_);
  value_ = decay_ * value_ + Eigen::Vector3d(x, y, z);
}

}  // namespace deepnav::sim
