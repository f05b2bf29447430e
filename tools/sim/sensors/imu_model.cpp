#include "tools/sim/sensors/imu_model.h"

#include <cmath>

#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {
constexpr double kSqrtSPerSqrtH = 60.0;  // sqrt(3600 s / h)
constexpr double kSPerH = 3600.0;
}  // namespace

bool ImuModel::init(const ImuConfig& config, std::uint64_t seed, std::string* error) {
  if (!(config.rate_hz > 0.0)) {
    if (error) *error = "imu: rate_hz must be > 0";
    return false;
  }
  rng_ = NormalRng(seed);
  R_imu_robot_ = rotationFromRpyDeg(config.mount_rpy_deg).transpose();
  const double dt_s = 1.0 / config.rate_hz;
  // A noise density N [unit/sqrt(s)] sampled at rate r has per-sample sigma N * sqrt(r).
  const double gyro_density = config.gyro_noise_deg_per_sqrt_h * kDegToRad / kSqrtSPerSqrtH;
  const double accel_density = config.accel_noise_mps_per_sqrt_h / kSqrtSPerSqrtH;
  gyro_sigma_radps_ = gyro_density / std::sqrt(dt_s);
  accel_sigma_mps2_ = accel_density / std::sqrt(dt_s);
  // A random walk of density K [unit/sqrt(s)] grows by K * sqrt(dt) per step.
  const double gyro_rw = config.gyro_bias_rw_deg_per_h_per_sqrt_h * kDegToRad / kSPerH / kSqrtSPerSqrtH;
  const double accel_rw = config.accel_bias_rw_mps2_per_sqrt_h / kSqrtSPerSqrtH;
  gyro_bias_step_radps_ = gyro_rw * std::sqrt(dt_s);
  accel_bias_step_mps2_ = accel_rw * std::sqrt(dt_s);
  gyro_bias_radps_ = randomVector(config.gyro_initial_bias_deg_per_h * kDegToRad / kSPerH);
  accel_bias_mps2_ = randomVector(config.accel_initial_bias_mps2);
  return true;
}

Eigen::Vector3d ImuModel::randomVector(double sigma) {
  // Explicit order of draws (x, y, z): reproducible whatever the compiler does with evaluation order.
  const double x = rng_.normal(sigma);
  const double y = rng_.normal(sigma);
  const double z = rng_.normal(sigma);
  return {x, y, z};
}

ImuSample ImuModel::measure(const KinematicState& truth, TimeUs t_us) {
  ImuSample s;
  s.t_us = t_us;
  s.w_imu_radps = R_imu_robot_ * truth.w_robot_radps + gyro_bias_radps_ + randomVector(gyro_sigma_radps_);
  s.f_imu_mps2 = R_imu_robot_ * truth.f_robot_mps2 + accel_bias_mps2_ + randomVector(accel_sigma_mps2_);
  gyro_bias_radps_ += randomVector(gyro_bias_step_radps_);
  accel_bias_mps2_ += randomVector(accel_bias_step_mps2_);
  return s;
}

}  // namespace deepnav::sim
