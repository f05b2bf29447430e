#include "tools/sim/sensors/compass_model.h"

#include <numbers>

#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {
// Sub-stream (of the compass's own seed) for the per-dive residual bias: the noise stream is untouched.
constexpr std::uint64_t kResidualBiasStream = 1000;
}  // namespace

bool CompassModel::init(const CompassConfig& config, const PanelGeometry& panel, double seabed_z_in_odom_m,
                        std::uint64_t seed, std::string* error) {
  if (!(config.rate_hz > 0.0)) {
    if (error) *error = "compass: rate_hz must be > 0";
    return false;
  }
  if (config.true_north && config.magneticErrorsActive()) {
    if (error) *error = "compass: deviation and the panel's magnetic field need a magnetic compass (true_north false)";
    return false;
  }
  config_ = config;
  rng_ = NormalRng(seed);
  residual_bias_rad_ = 0.0;
  if (config.residual_bias_deg != 0.0 || config.residual_bias_sigma_deg != 0.0) {
    NormalRng draw(NormalRng::subSeed(seed, kResidualBiasStream));
    residual_bias_rad_ = (config.residual_bias_deg + draw.normal(config.residual_bias_sigma_deg)) * kDegToRad;
  }
  earth_ = EarthField{config.earth_horizontal_field_ut, config.earth_vertical_field_ut,
                      config.true_north ? 0.0 : config.declination_deg * kDegToRad};
  if (config.panel_magnet.active()) panel_field_.init(config.panel_magnet, panel, seabed_z_in_odom_m, earth_);
  return true;
}

double CompassModel::noiseSigma_rad() const { return config_.noise_deg * kDegToRad; }

double CompassModel::panelHeadingError_rad(const KinematicState& truth) const {
  if (!config_.panel_magnet.active()) return 0.0;
  const Eigen::Vector3d p_compass_in_odom_m =
      truth.p_robot_in_odom_m + truth.q_odom_robot * toVector(config_.p_compass_in_robot_m);
  return disturbanceHeadingError_rad(earth_.inOdom_ut(), panel_field_.field_ut(p_compass_in_odom_m));
}

double CompassModel::noiselessHeading_rad(const KinematicState& truth) const {
  const double declination_rad = config_.true_north ? 0.0 : config_.declination_deg * kDegToRad;
  if (!config_.magneticErrorsActive() && residual_bias_rad_ == 0.0)
    return wrapTo2Pi(std::numbers::pi / 2.0 - truth.yaw_rad - declination_rad + config_.bias_deg * kDegToRad);
  const double psi_rad = wrapTo2Pi(std::numbers::pi / 2.0 - truth.yaw_rad - declination_rad +
                                   panelHeadingError_rad(truth));
  const double deviation_rad = config_.deviation.at_deg(psi_rad) * kDegToRad;
  return wrapTo2Pi(psi_rad + deviation_rad + config_.bias_deg * kDegToRad + residual_bias_rad_);
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
