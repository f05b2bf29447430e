#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/metrics/stamped_pose.h"

namespace deepnav {

// Euclidean distance between estimated and true positions, metres.
double positionError(const Eigen::Vector3d& p_est_m, const Eigen::Vector3d& p_true_m);

// Geodesic distance on SO(3): the angle of q_true^-1 q_est, radians in [0, pi].
double orientationError(const Eigen::Quaterniond& q_est, const Eigen::Quaterniond& q_true);

// mean, standard deviation (sample, N - 1 in the denominator; 0 for N < 2), RMS and maximum.
struct ErrorStats {
  double mean = 0.0;
  double std = 0.0;
  double rms = 0.0;
  double max = 0.0;
  std::size_t count = 0;
};
ErrorStats summarizeErrors(std::span<const double> errors);

// Per-epoch errors of an estimate against ground truth already associated pose by pose (same length;
// see trajectory_association.h), and their summaries.
struct TrajectoryErrors {
  std::vector<double> position_m;
  std::vector<double> orientation_rad;
  ErrorStats position;
  ErrorStats orientation;
};
TrajectoryErrors trajectoryErrors(std::span<const StampedPose> estimate, std::span<const StampedPose> truth);

}  // namespace deepnav
