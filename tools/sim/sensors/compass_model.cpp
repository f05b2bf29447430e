#include "tools/sim/sensors/compass_model.h"

#include <numbers>

#include "tools/sim/rotation.h"

namespace deepnav::sim {

bool CompassModel::init(const CompassConfig& config, std::uint64_t seed, std::string* error) {
  if (!(config.rate_hz > 0.0)) {
    if (error) *error = "compass: rate_hz must be > 0";
    return false;
  }
  config_ = config;
  rng_ = NormalRng(seed);
  return true;
}

double CompassModel::noiseSigma_rad() const { return config_.noise_deg * kDegToRad; }

double CompassModel::noiselessHeading_rad(const KinematicState& truth) const {
  const double declination_rad = config_.true_north ? 0.0 : config_.declination_deg * kDegToRad;
  return wrapTo2Pi(std::numbers::pi / 2.0 - truth.yaw_rad - declination_rad + config_.bias_deg * kDegToRad);
}

HeadingSample CompassModel::measure(const KinematicState& truth, TimeUs t_us) {
  HeadingSample s;
  s.t_us = t_us;
  s.heading_rad = wrapTo2Pi(noiselessHeading_rad(truth) + rng_.normal(noiseSigma_rad()));
  s.is_true = config_.true_north;
  s.sigma_rad = noiseSigma_rad();
  return s;
}

}  // namespace deepnav::sim
