#include "tools/sim/sensors/depth_model.h"

#include <cmath>

#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {
constexpr double kUsPerHour = 3600e6;
}  // namespace

bool DepthModel::init(const DepthConfig& config, const EnvironmentConfig& environment, std::uint64_t seed,
                      std::string* error) {
  if (!(config.rate_hz > 0.0) || !(environment.water_density_kgpm3 > 0.0) || !(environment.gravity_mps2 > 0.0) ||
      !(environment.water_density_kgpm3 + config.density_error_kgpm3 > 0.0)) {
    if (error) *error = "depth: rate_hz, water density (with its error) and gravity must be > 0";
    return false;
  }
  config_ = config;
  environment_ = environment;
  rng_ = NormalRng(seed);
  extra_errors_ = config.resolution_pa != 0.0 || config.density_error_kgpm3 != 0.0 || config.drift_m_per_h != 0.0;
  return true;
}

double DepthModel::noiseSigma_pa() const {
  return config_.noise_m * environment_.water_density_kgpm3 * environment_.gravity_mps2;
}

double DepthModel::scaleFactor() const {
  return (environment_.water_density_kgpm3 + config_.density_error_kgpm3) / environment_.water_density_kgpm3;
}

double DepthModel::trueDepth_m(const KinematicState& truth) const {
  const Eigen::Vector3d p_sensor_in_odom =
      truth.p_robot_in_odom_m + truth.q_odom_robot * toVector(config_.p_sensor_in_robot_m);
  return environment_.odom_origin_depth_m - p_sensor_in_odom.z();
}

DepthSample DepthModel::measure(const KinematicState& truth, TimeUs t_us) {
  const double rho_g = environment_.water_density_kgpm3 * environment_.gravity_mps2;
  DepthSample s;
  s.t_us = t_us;
  if (!extra_errors_) {
    s.pressure_pa = environment_.atmospheric_pressure_pa + rho_g * trueDepth_m(truth) + rng_.normal(noiseSigma_pa());
  } else {
    const double rho_g_true = (environment_.water_density_kgpm3 + config_.density_error_kgpm3) * environment_.gravity_mps2;
    const double drift_pa = rho_g * config_.drift_m_per_h * (static_cast<double>(t_us) / kUsPerHour);
    s.pressure_pa = environment_.atmospheric_pressure_pa + rho_g_true * trueDepth_m(truth) + drift_pa +
                    rng_.normal(noiseSigma_pa());
    if (config_.resolution_pa > 0.0)
      s.pressure_pa = std::round(s.pressure_pa / config_.resolution_pa) * config_.resolution_pa;
  }
  s.depth_m = (s.pressure_pa - environment_.atmospheric_pressure_pa) / rho_g;
  s.sigma_m = config_.noise_m;
  return s;
}

}  // namespace deepnav::sim
