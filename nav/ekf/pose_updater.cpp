#include "nav/ekf/pose_updater.h"

#include <cmath>

#include <Eigen/Cholesky>

#include "base/so3.h"

namespace deepnav {

bool isValidPose(const PoseMeasurement& m) {
  if (!m.p_robot_in_odom_m.allFinite() || !m.q_odom_robot.coeffs().allFinite()) return false;
  if (std::abs(m.q_odom_robot.norm() - 1.0) > 1e-3) return false;
  if (!m.cov_pose.allFinite() || !m.cov_pose.isApprox(m.cov_pose.transpose(), 1e-9)) return false;
  if ((m.cov_pose.diagonal().array() <= 0.0).any()) return false;
  return Eigen::LLT<Eigen::Matrix<double, 6, 6>>(m.cov_pose).info() == Eigen::Success;
}

bool linearizePose(const FilterState& s, const PoseMeasurement& m, Linearization* out) {
  const Eigen::Matrix3d R_hat = s.x.q_odom_robot.toRotationMatrix();
  const Eigen::Matrix3d R_meas = m.q_odom_robot.normalized().toRotationMatrix();
  const Eigen::Vector3d r_theta = logSo3(R_meas * R_hat.transpose());
  out->reset(6, s.dim());
  out->residual.head<3>() = m.p_robot_in_odom_m - s.x.p_robot_in_odom_m;
  out->residual.tail<3>() = r_theta;
  out->H.block<3, 3>(0, es::kP).setIdentity();
  out->H.block<3, 3>(3, es::kTheta) = rightJacobianInverseSo3(r_theta);
  out->R = m.cov_pose;
  return true;
}

}  // namespace deepnav
