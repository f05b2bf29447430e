#include "tools/sim/sensors/attitude_model.h"

#include "tools/sim/rotation.h"

namespace deepnav::sim {

bool AttitudeModel::init(const AttitudeConfig& config, std::uint64_t seed, std::string* error) {
  if (!(config.rate_hz > 0.0)) {
    if (error) *error = "attitude: rate_hz must be > 0";
    return false;
  }
  config_ = config;
  rng_ = NormalRng(seed);
  return true;
}

double AttitudeModel::noiseSigma_rad() const { return config_.noise_deg * kDegToRad; }

AttitudeSample AttitudeModel::measure(const KinematicState& truth, TimeUs t_us) {
  AttitudeSample s;
  s.t_us = t_us;
  const double roll_noise = rng_.normal(noiseSigma_rad());
  const double pitch_noise = rng_.normal(noiseSigma_rad());
  s.roll_rad = truth.roll_rad + roll_noise;
  s.pitch_rad = truth.pitch_rad + pitch_noise;
  s.sigma_rad = noiseSigma_rad();
  return s;
}

}  // namespace deepnav::sim
