#pragma once
#include <Eigen/Core>

#include "nav/types/truth_sample.h"

namespace deepnav {

// True state of the robot at IMU rate for scoring the estimator (pose, velocity and rate: TruthSample),
// plus the simulated IMU's biases at this time (IMU frame), to score bias estimates (zero when the IMU
// is off).
struct GroundTruthSample : TruthSample {
  Eigen::Vector3d gyro_bias_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_bias_mps2 = Eigen::Vector3d::Zero();
};

}  // namespace deepnav
