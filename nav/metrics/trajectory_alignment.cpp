#include "nav/metrics/trajectory_alignment.h"

#include <algorithm>
#include <vector>

#include <Eigen/SVD>

namespace deepnav {

Eigen::Isometry3d alignRigid(std::span<const StampedPose> estimate, std::span<const StampedPose> truth) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  const std::size_t n = std::min(estimate.size(), truth.size());
  if (n < 3) return T;
  Eigen::Vector3d mean_est = Eigen::Vector3d::Zero(), mean_true = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    mean_est += estimate[i].p_robot_in_odom_m;
    mean_true += truth[i].p_robot_in_odom_m;
  }
  mean_est /= static_cast<double>(n);
  mean_true /= static_cast<double>(n);
  // Cross-covariance Sigma = 1/n sum (p_true - mu_true)(p_est - mu_est)^T = U D V^T; R = U S V^T with
  // S = diag(1, 1, det(U) det(V)) so that R is a rotation, not a reflection (Umeyama eq. 39-40).
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    sigma += (truth[i].p_robot_in_odom_m - mean_true) * (estimate[i].p_robot_in_odom_m - mean_est).transpose();
  }
  sigma /= static_cast<double>(n);
  if (!(sigma.norm() > 0.0)) return T;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d s = Eigen::Vector3d::Ones();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) s(2) = -1.0;
  T.linear() = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();
  T.translation() = mean_true - T.linear() * mean_est;
  return T;
}

AlignedTrajectoryErrors alignedTrajectoryErrors(std::span<const StampedPose> estimate,
                                                std::span<const StampedPose> truth) {
  AlignedTrajectoryErrors out;
  out.T_align = alignRigid(estimate, truth);
  const Eigen::Quaterniond q_align(out.T_align.linear());
  std::vector<StampedPose> aligned(estimate.begin(), estimate.end());
  for (StampedPose& p : aligned) {
    p.p_robot_in_odom_m = out.T_align * p.p_robot_in_odom_m;
    p.q_odom_robot = q_align * p.q_odom_robot;
  }
  out.errors = trajectoryErrors(aligned, truth);
  return out;
}

}  // namespace deepnav
