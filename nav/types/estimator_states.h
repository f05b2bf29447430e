#pragma once
#include <array>

#include "nav/types/time.h"

namespace deepnav {

// The filter's estimates of the sensors' errors and their 1-sigmas (topic /nav/estimator_states): the IMU
// biases (robot frame) and the systematic states the board enabled (nav/ekf/systematic_states.h); a
// state not estimated is flagged off and left at 0.
struct EstimatorStates {
  TimeUs t_us = 0;
  std::array<double, 3> gyro_bias_radps{}, gyro_bias_sigma_radps{};
  std::array<double, 3> accel_bias_mps2{}, accel_bias_sigma_mps2{};
  bool dvl_scale_estimated = false;
  double dvl_scale = 0.0, dvl_scale_sigma = 0.0;  // fraction: v_measured = (1 + s) v_true
  bool dvl_misalignment_estimated = false;
  std::array<double, 3> dvl_misalignment_rad{}, dvl_misalignment_sigma_rad{};  // rotation vector, DVL axes
  bool dvl_bias_estimated = false;
  std::array<double, 3> dvl_bias_mps{}, dvl_bias_sigma_mps{};  // DVL axes: v_measured = ... + b
  bool heading_bias_estimated = false;
  double heading_bias_rad = 0.0, heading_bias_sigma_rad = 0.0;
  bool heading_deviation_estimated = false;
  // B sin psi, C cos psi, D sin 2psi, E cos 2psi of the compass deviation, psi the magnetic heading.
  std::array<double, 4> heading_deviation_rad{}, heading_deviation_sigma_rad{};
};

}  // namespace deepnav
