#include "nav/metrics/trajectory_errors.h"

#include <algorithm>
#include <cmath>

namespace deepnav {

double positionError(const Eigen::Vector3d& p_est_m, const Eigen::Vector3d& p_true_m) {
  return (p_est_m - p_true_m).norm();
}

double orientationError(const Eigen::Quaterniond& q_est, const Eigen::Quaterniond& q_true) {
  return q_est.normalized().angularDistance(q_true.normalized());
}

ErrorStats summarizeErrors(std::span<const double> errors) {
  ErrorStats s;
  s.count = errors.size();
  if (errors.empty()) return s;
  double sum = 0.0, sum2 = 0.0;
  for (double e : errors) {
    sum += e;
    sum2 += e * e;
    s.max = std::max(s.max, e);
  }
  const double n = static_cast<double>(errors.size());
  s.mean = sum / n;
  s.rms = std::sqrt(sum2 / n);
  if (errors.size() > 1) {
    double ss = 0.0;
    for (double e : errors) ss += (e - s.mean) * (e - s.mean);
    s.std = std::sqrt(ss / (n - 1.0));
  }
  return s;
}

TrajectoryErrors trajectoryErrors(std::span<const StampedPose> estimate, std::span<const StampedPose> truth) {
  TrajectoryErrors out;
  const std::size_t n = std::min(estimate.size(), truth.size());
  out.position_m.reserve(n);
  out.orientation_rad.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    out.position_m.push_back(positionError(estimate[i].p_robot_in_odom_m, truth[i].p_robot_in_odom_m));
    out.orientation_rad.push_back(orientationError(estimate[i].q_odom_robot, truth[i].q_odom_robot));
  }
  out.position = summarizeErrors(out.position_m);
  out.orientation = summarizeErrors(out.orientation_rad);
  return out;
}

}  // namespace deepnav
