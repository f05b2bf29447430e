#pragma once
#include <array>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "nav/types/imu_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"
#include "tools/sim/sensors/imu_gauss_markov.h"
#include "tools/sim/sensors/imu_vibration.h"

namespace deepnav::sim {

// Scenario key `imu`. Defaults: a MEMS tactical-grade unit with white noise, random-walk biases and a
// turn-on bias only (every other error term off). `imu.grade` (imu_grades.h) sets them from a data sheet.
// Noise densities are in the units of data sheets; the model converts them to per-sample standard
// deviations at `rate_hz`.
struct ImuConfig {
  bool enabled = true;
  double rate_hz = 100.0;
  double gyro_noise_deg_per_sqrt_h = 0.15;               // angular random walk (white rate noise)
  double gyro_bias_rw_deg_per_h_per_sqrt_h = 0.5;        // rate random walk: bias drift
  double gyro_initial_bias_deg_per_h = 3.0;              // turn-on bias: 1-sigma per axis, drawn once at start
  double gyro_bias_instability_deg_per_h = 0.0;          // Allan floor of a Gauss-Markov bias (imu_gauss_markov.h)
  double gyro_bias_correlation_time_s = 300.0;           // its correlation time T
  double gyro_scale_factor_ppm = 0.0;                    // 1-sigma per axis, drawn once per dive
  double gyro_misalignment_mrad = 0.0;                   // 1-sigma per off-diagonal term, drawn once per dive
  double accel_noise_mps_per_sqrt_h = 0.03;              // velocity random walk (white accel noise)
  double accel_bias_rw_mps2_per_sqrt_h = 0.001;          // accel bias drift
  double accel_initial_bias_mps2 = 0.005;                // 1-sigma per axis, drawn once at start
  double accel_bias_instability_mps2 = 0.0;
  double accel_bias_correlation_time_s = 300.0;
  double accel_scale_factor_ppm = 0.0;
  double accel_misalignment_mrad = 0.0;
  std::array<double, 3> mount_rpy_deg{0.0, 0.0, 0.0};    // R_robot_imu
  std::array<double, 3> p_imu_in_robot_m{0.0, 0.0, 0.0};  // lever arm of the accelerometers' origin
  double vibration_accel_rms_mps2 = 0.0;                 // thruster vibration, per axis (imu_vibration.h)
  double vibration_gyro_rms_deg_per_s = 0.0;
  std::array<double, 3> vibration_frequencies_hz{73.0, 118.0, 161.0};  // blade-pass tones

  bool operator==(const ImuConfig&) const = default;
};

// Gyro and accelerometer (IMU frame I, R_imu_robot = mount^T, T_g, T_a from imu_scale_misalignment.h):
//   w_imu = T_g R_imu_robot w_robot + b_g + n_g + v_g,
//   f_imu = T_a R_imu_robot (f_robot + alpha x r + w x (w x r)) + b_a + n_a + v_a,
// r = p_imu_in_robot_m, alpha the robot's angular acceleration; b = turn-on + random walk
// (b(k+1) = b(k) + sigma_rw sqrt(dt) n) + Gauss-Markov; n white; v thruster vibration.
// Random numbers: the white noise, turn-on and random-walk biases come from the generator seeded with
// `seed` (in the order they always had); scale factor and misalignment, the Gauss-Markov biases and the
// vibration each from their own sub-stream (NormalRng::subSeed(seed, 1000 / 1001 / 1002)), drawn only
// when the term is on: with those terms off the stream is the one of the model without them.
// measure() must be called once per IMU period, in time order: each call advances the biases one step.
class ImuModel {
 public:
  bool init(const ImuConfig& config, std::uint64_t seed, std::string* error);
  ImuSample measure(const KinematicState& truth, TimeUs t_us);

  // The additive biases in effect for the next measure() (turn-on + random walk + Gauss-Markov).
  Eigen::Vector3d gyroBias_radps() const;
  Eigen::Vector3d accelBias_mps2() const;
  // Per-sample standard deviations of the white noise and of one bias step.
  double gyroNoiseSigma_radps() const { return gyro_sigma_radps_; }
  double accelNoiseSigma_mps2() const { return accel_sigma_mps2_; }
  double gyroBiasStepSigma_radps() const { return gyro_bias_step_radps_; }
  double accelBiasStepSigma_mps2() const { return accel_bias_step_mps2_; }
  // This dive's T_g and T_a (identity when both terms are off).
  const Eigen::Matrix3d& gyroScaleMisalignment() const { return T_gyro_; }
  const Eigen::Matrix3d& accelScaleMisalignment() const { return T_accel_; }

 private:
  Eigen::Vector3d randomVector(double sigma);
  void initSystematicErrors(const ImuConfig& config, std::uint64_t seed);
  void initGaussMarkov(const ImuConfig& config, std::uint64_t seed, double dt_s);
  void initVibration(const ImuConfig& config, std::uint64_t seed);
  Eigen::Vector3d specificForceAtImu_robot(const KinematicState& truth) const;

  NormalRng rng_;
  NormalRng gauss_markov_rng_;
  NormalRng vibration_rng_;
  Eigen::Matrix3d R_imu_robot_ = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d T_gyro_ = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d T_accel_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_imu_in_robot_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_bias_radps_ = Eigen::Vector3d::Zero();  // turn-on + random walk
  Eigen::Vector3d accel_bias_mps2_ = Eigen::Vector3d::Zero();
  GaussMarkov3 gyro_gauss_markov_;
  GaussMarkov3 accel_gauss_markov_;
  ImuVibration gyro_vibration_;
  ImuVibration accel_vibration_;
  double gyro_sigma_radps_ = 0.0;
  double accel_sigma_mps2_ = 0.0;
  double gyro_bias_step_radps_ = 0.0;
  double accel_bias_step_mps2_ = 0.0;
  // Which optional terms are on: the off ones are skipped entirely (no identity products).
  bool has_gyro_T_ = false;
  bool has_accel_T_ = false;
  bool has_lever_arm_ = false;
  bool has_gyro_gauss_markov_ = false;
  bool has_accel_gauss_markov_ = false;
  bool has_gyro_vibration_ = false;
  bool has_accel_vibration_ = false;
};

}  // namespace deepnav::sim
