#include "tools/sim/sensors/imu_model.h"

#include <cmath>

#include "tools/sim/rotation.h"
#include "tools/sim/sensors/imu_scale_misalignment.h"

namespace deepnav::sim {

namespace {
constexpr double kSqrtSPerSqrtH = 60.0;  // sqrt(3600 s / h)
constexpr double kSPerH = 3600.0;
// Sub-stream ids of the optional terms (NormalRng::subSeed of the model's seed).
constexpr std::uint64_t kScaleMisalignmentStream = 1000;
constexpr std::uint64_t kGaussMarkovStream = 1001;
constexpr std::uint64_t kVibrationStream = 1002;

bool isNonZero(const std::array<double, 3>& v) { return v[0] != 0.0 || v[1] != 0.0 || v[2] != 0.0; }
}  // namespace

bool ImuModel::init(const ImuConfig& config, std::uint64_t seed, std::string* error) {
  if (!(config.rate_hz > 0.0) || !(config.gyro_bias_correlation_time_s > 0.0) ||
      !(config.accel_bias_correlation_time_s > 0.0)) {
    if (error) *error = "imu: rate_hz and the bias correlation times must be > 0";
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
  initSystematicErrors(config, seed);
  initGaussMarkov(config, seed, dt_s);
  initVibration(config, seed);
  return true;
}

void ImuModel::initSystematicErrors(const ImuConfig& config, std::uint64_t seed) {
  has_gyro_T_ = config.gyro_scale_factor_ppm > 0.0 || config.gyro_misalignment_mrad > 0.0;
  has_accel_T_ = config.accel_scale_factor_ppm > 0.0 || config.accel_misalignment_mrad > 0.0;
  T_gyro_.setIdentity();
  T_accel_.setIdentity();
  // Both triads are always drawn from the sub-stream when either is on, so switching one term on does
  // not change the other's draw.
  if (has_gyro_T_ || has_accel_T_) {
    NormalRng rng(NormalRng::subSeed(seed, kScaleMisalignmentStream));
    const Eigen::Matrix3d T_gyro = drawScaleMisalignment(config.gyro_scale_factor_ppm, config.gyro_misalignment_mrad, &rng);
    const Eigen::Matrix3d T_accel = drawScaleMisalignment(config.accel_scale_factor_ppm, config.accel_misalignment_mrad, &rng);
    if (has_gyro_T_) T_gyro_ = T_gyro;
    if (has_accel_T_) T_accel_ = T_accel;
  }
  has_lever_arm_ = isNonZero(config.p_imu_in_robot_m);
  p_imu_in_robot_m_ = {config.p_imu_in_robot_m[0], config.p_imu_in_robot_m[1], config.p_imu_in_robot_m[2]};
}

void ImuModel::initGaussMarkov(const ImuConfig& config, std::uint64_t seed, double dt_s) {
  has_gyro_gauss_markov_ = config.gyro_bias_instability_deg_per_h > 0.0;
  has_accel_gauss_markov_ = config.accel_bias_instability_mps2 > 0.0;
  gauss_markov_rng_ = NormalRng(NormalRng::subSeed(seed, kGaussMarkovStream));
  // Draw both (zero sigma when off) so one term's switch does not shift the other's sequence.
  const double gyro_sigma =
      config.gyro_bias_instability_deg_per_h * kDegToRad / kSPerH / kGaussMarkovAdevPeakOverSigma;
  const double accel_sigma = config.accel_bias_instability_mps2 / kGaussMarkovAdevPeakOverSigma;
  gyro_gauss_markov_.init(gyro_sigma, config.gyro_bias_correlation_time_s, dt_s, &gauss_markov_rng_);
  accel_gauss_markov_.init(accel_sigma, config.accel_bias_correlation_time_s, dt_s, &gauss_markov_rng_);
}

void ImuModel::initVibration(const ImuConfig& config, std::uint64_t seed) {
  has_gyro_vibration_ = config.vibration_gyro_rms_deg_per_s > 0.0;
  has_accel_vibration_ = config.vibration_accel_rms_mps2 > 0.0;
  vibration_rng_ = NormalRng(NormalRng::subSeed(seed, kVibrationStream));
  gyro_vibration_.init(config.vibration_gyro_rms_deg_per_s * kDegToRad, config.vibration_frequencies_hz,
                       &vibration_rng_);
  accel_vibration_.init(config.vibration_accel_rms_mps2, config.vibration_frequencies_hz, &vibration_rng_);
}

Eigen::Vector3d ImuModel::randomVector(double sigma) {
  // Explicit order of draws (x, y, z): reproducible whatever the compiler does with evaluation order.
  const double x = rng_.normal(sigma);
  const double y = rng_.normal(sigma);
  const double z = rng_.normal(sigma);
  return {x, y, z};
}

Eigen::Vector3d ImuModel::gyroBias_radps() const {
  if (!has_gyro_gauss_markov_) return gyro_bias_radps_;
  return gyro_bias_radps_ + gyro_gauss_markov_.value();
}

Eigen::Vector3d ImuModel::accelBias_mps2() const {
  if (!has_accel_gauss_markov_) return accel_bias_mps2_;
  return accel_bias_mps2_ + accel_gauss_markov_.value();
}

Eigen::Vector3d ImuModel::specificForceAtImu_robot(const KinematicState& truth) const {
  if (!has_lever_arm_) return truth.f_robot_mps2;
  // Rigid body: a_imu = a_robot + alpha x r + w x (w x r), and gravity is the same at both points.
  const Eigen::Vector3d& w = truth.w_robot_radps;
  return truth.f_robot_mps2 + truth.alpha_robot_radps2.cross(p_imu_in_robot_m_) +
         w.cross(w.cross(p_imu_in_robot_m_));
}

ImuSample ImuModel::measure(const KinematicState& truth, TimeUs t_us) {
  Eigen::Vector3d w_imu = R_imu_robot_ * truth.w_robot_radps;
  Eigen::Vector3d f_imu = R_imu_robot_ * specificForceAtImu_robot(truth);
  if (has_gyro_T_) w_imu = T_gyro_ * w_imu;
  if (has_accel_T_) f_imu = T_accel_ * f_imu;
  ImuSample s;
  s.t_us = t_us;
  s.w_imu_radps = w_imu + gyroBias_radps() + randomVector(gyro_sigma_radps_);
  s.f_imu_mps2 = f_imu + accelBias_mps2() + randomVector(accel_sigma_mps2_);
  // The optional terms draw for both triads when either is on, so switching one on or off does not
  // shift the other's sequence.
  if (has_gyro_vibration_ || has_accel_vibration_) {
    const Eigen::Vector3d v_gyro = gyro_vibration_.sample(t_us, &vibration_rng_);
    const Eigen::Vector3d v_accel = accel_vibration_.sample(t_us, &vibration_rng_);
    if (has_gyro_vibration_) s.w_imu_radps += v_gyro;
    if (has_accel_vibration_) s.f_imu_mps2 += v_accel;
  }
  gyro_bias_radps_ += randomVector(gyro_bias_step_radps_);
  accel_bias_mps2_ += randomVector(accel_bias_step_mps2_);
  if (has_gyro_gauss_markov_ || has_accel_gauss_markov_) {
    gyro_gauss_markov_.step(&gauss_markov_rng_);
    accel_gauss_markov_.step(&gauss_markov_rng_);
  }
  return s;
}

}  // namespace deepnav::sim
