#include "tools/sim/sensors/attitude_model.h"

#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {
// Sub-stream (of the attitude's own seed) for the per-dive biases: the noise stream is untouched.
constexpr std::uint64_t kBiasStream = 1000;
}  // namespace

bool AttitudeModel::init(const AttitudeConfig& config, std::uint64_t seed, std::string* error) {
  if (!(config.rate_hz > 0.0)) {
    if (error) *error = "attitude: rate_hz must be > 0";
    return false;
  }
  config_ = config;
  rng_ = NormalRng(seed);
  biased_ = config.roll_bias_deg != 0.0 || config.pitch_bias_deg != 0.0 || config.bias_sigma_deg != 0.0;
  roll_bias_rad_ = 0.0;
  pitch_bias_rad_ = 0.0;
  if (biased_) {
    NormalRng draw(NormalRng::subSeed(seed, kBiasStream));
    roll_bias_rad_ = (config.roll_bias_deg + draw.normal(config.bias_sigma_deg)) * kDegToRad;
    pitch_bias_rad_ = (config.pitch_bias_deg + draw.normal(config.bias_sigma_deg)) * kDegToRad;
  }
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
  if (biased_) {
    s.roll_rad += roll_bias_rad_;
    s.pitch_rad += pitch_bias_rad_;
  }
  s.sigma_rad = noiseSigma_rad();
  return s;
}

}  // namespace deepnav::sim
