#pragma once
#include <string>

#include <Eigen/Core>

#include "nav/ekf/ekf.h"
#include "nav/ekf/systematic_states.h"

namespace deepnav {

// The filter's estimates of the sensors' errors at the end of a replay, with their 1-sigmas: the IMU
// biases (robot frame) and the systematic states the board enabled (nav/ekf/systematic_states.h).
struct EstimatorStatesReport {
  bool valid = false;  // the filter was aligned
  Eigen::Vector3d b_gyro_radps = Eigen::Vector3d::Zero(), b_gyro_sigma_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d b_accel_mps2 = Eigen::Vector3d::Zero(), b_accel_sigma_mps2 = Eigen::Vector3d::Zero();
  SystematicEstimates systematic;
};

EstimatorStatesReport estimatorStatesReport(const Ekf& ekf);

// summary.json's "estimator_states": {"gyro_bias_radps": {"value": [..], "sigma": [..]}, ...}; a
// systematic state the board did not enable is null. Angles in rad, the DVL scale as a fraction.
std::string estimatorStatesJson(const EstimatorStatesReport& r);

}  // namespace deepnav
