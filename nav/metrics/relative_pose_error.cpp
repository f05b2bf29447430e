#include "nav/metrics/relative_pose_error.h"

#include <algorithm>

#include <Eigen/Geometry>

namespace deepnav {
namespace {

Eigen::Isometry3d toIsometry(const StampedPose& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = p.q_odom_robot.normalized().toRotationMatrix();
  T.translation() = p.p_robot_in_odom_m;
  return T;
}

void addPair(std::span<const StampedPose> est, std::span<const StampedPose> truth, std::size_t i, std::size_t j,
             double length_m, RelativePoseErrors* out) {
  const Eigen::Isometry3d d_true = toIsometry(truth[i]).inverse() * toIsometry(truth[j]);
  const Eigen::Isometry3d d_est = toIsometry(est[i]).inverse() * toIsometry(est[j]);
  const Eigen::Isometry3d E = d_true.inverse() * d_est;
  out->length_m.push_back(length_m);
  out->translation_m.push_back(E.translation().norm());
  out->rotation_rad.push_back(Eigen::AngleAxisd(E.linear()).angle());
}

}  // namespace

RelativePoseErrors relativePoseErrors(std::span<const StampedPose> estimate, std::span<const StampedPose> truth,
                                      double delta_m) {
  RelativePoseErrors out;
  out.delta_m = delta_m;
  const std::size_t n = std::min(estimate.size(), truth.size());
  if (n < 2 || !(delta_m > 0.0)) return out;
  std::size_t start = 0;
  double travelled_m = 0.0;
  for (std::size_t k = 1; k < n; ++k) {
    travelled_m += (truth[k].p_robot_in_odom_m - truth[k - 1].p_robot_in_odom_m).norm();
    if (travelled_m < delta_m) continue;
    addPair(estimate, truth, start, k, travelled_m, &out);
    start = k;
    travelled_m = 0.0;
  }
  std::vector<double> percent(out.length_m.size()), per_m(out.length_m.size());
  for (std::size_t k = 0; k < out.length_m.size(); ++k) {
    percent[k] = 100.0 * out.translation_m[k] / out.length_m[k];
    per_m[k] = out.rotation_rad[k] / out.length_m[k];
  }
  out.translation = summarizeErrors(out.translation_m);
  out.rotation = summarizeErrors(out.rotation_rad);
  out.translation_percent = summarizeErrors(percent);
  out.rotation_rad_per_m = summarizeErrors(per_m);
  return out;
}

}  // namespace deepnav
