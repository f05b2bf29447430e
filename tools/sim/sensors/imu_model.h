#pragma once
#include <array>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "nav/types/imu_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// Scenario key `imu`. Defaults: a MEMS tactical-grade unit. Noise densities are in the units of data
// sheets; the model converts them to per-sample standard deviations at `rate_hz`.
struct ImuConfig {
  bool enabled = true;
  double rate_hz = 100.0;
  double gyro_noise_deg_per_sqrt_h = 0.15;               // angular random walk (white rate noise)
  double gyro_bias_rw_deg_per_h_per_sqrt_h = 0.5;        // rate random walk: bias drift
  double gyro_initial_bias_deg_per_h = 3.0;              // 1-sigma per axis, drawn once at start
  double accel_noise_mps_per_sqrt_h = 0.03;              // velocity random walk (white accel noise)
  double accel_bias_rw_mps2_per_sqrt_h = 0.001;          // accel bias drift
  double accel_initial_bias_mps2 = 0.005;                // 1-sigma per axis, drawn once at start
  std::array<double, 3> mount_rpy_deg{0.0, 0.0, 0.0};    // R_robot_imu; the IMU sits at the robot origin

  bool operator==(const ImuConfig&) const = default;
};

// Gyro and accelerometer with white noise and random-walk biases:
//   w_imu = R_imu_robot w_robot + b_g + n_g,   f_imu = R_imu_robot f_robot + b_a + n_a,
//   b(k+1) = b(k) + sigma_rw sqrt(dt) n.
// measure() must be called once per IMU period, in time order: each call advances the biases one step.
class ImuModel {
 public:
  bool init(const ImuConfig& config, std::uint64_t seed, std::string* error);
  ImuSample measure(const KinematicState& truth, TimeUs t_us);

  const Eigen::Vector3d& gyroBias_radps() const { return gyro_bias_radps_; }
  const Eigen::Vector3d& accelBias_mps2() const { return accel_bias_mps2_; }
  // Per-sample standard deviations of the white noise and of one bias step.
  double gyroNoiseSigma_radps() const { return gyro_sigma_radps_; }
  double accelNoiseSigma_mps2() const { return accel_sigma_mps2_; }
  double gyroBiasStepSigma_radps() const { return gyro_bias_step_radps_; }
  double accelBiasStepSigma_mps2() const { return accel_bias_step_mps2_; }

 private:
  Eigen::Vector3d randomVector(double sigma);

  NormalRng rng_;
  Eigen::Matrix3d R_imu_robot_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d gyro_bias_radps_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_mps2_ = Eigen::Vector3d::Zero();
  double gyro_sigma_radps_ = 0.0;
  double accel_sigma_mps2_ = 0.0;
  double gyro_bias_step_radps_ = 0.0;
  double accel_bias_step_mps2_ = 0.0;
};

}  // namespace deepnav::sim
