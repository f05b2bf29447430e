#include "nav/ekf/relative_pose_updater.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "base/so3.h"

namespace deepnav {

bool isValidRelativePose(const RelativePoseMeasurement& m) {
  if (!m.p_robotb_in_robota_m.allFinite() || !m.q_robota_robotb.coeffs().allFinite()) return false;
  if (std::abs(m.q_robota_robotb.norm() - 1.0) > 1e-3) return false;
  if (!m.cov.allFinite() || !m.cov.isApprox(m.cov.transpose(), 1e-9)) return false;
  const int first = m.has_translation ? 0 : 3;
  const int n = 6 - first;
  if ((m.cov.diagonal().tail(n).array() <= 0.0).any()) return false;
  using Block = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 6, 6>;
  const Block used = m.cov.block(first, first, n, n);
  return Eigen::LLT<Block>(used).info() == Eigen::Success;
}

int relativePoseConstrainedBasis(const MeasMatrix& cov, MeasMatrix* basis, MeasVector* variance) {
  const int rows = static_cast<int>(cov.rows());
  const Eigen::SelfAdjointEigenSolver<MeasMatrix> eig(cov);
  int k = 0;
  for (int i = 0; i < rows; ++i) k += eig.eigenvalues()(i) < kRelativePoseUnconstrainedVariance ? 1 : 0;
  basis->resize(rows, k);
  variance->resize(k);
  // Eigenvalues ascend: the first k are the constrained ones.
  for (int i = 0; i < k; ++i) {
    basis->col(i) = eig.eigenvectors().col(i);
    (*variance)(i) = eig.eigenvalues()(i);
  }
  return k;
}

namespace {

// Keeps only the constrained directions of a linearised relative pose (see the header).
bool projectOnConstrained(Linearization* lin) {
  const Eigen::SelfAdjointEigenSolver<MeasMatrix> eig(lin->R, Eigen::EigenvaluesOnly);
  if (eig.eigenvalues().maxCoeff() < kRelativePoseUnconstrainedVariance) return true;  // all measured: as is
  MeasMatrix U;
  MeasVector variance;
  const int k = relativePoseConstrainedBasis(lin->R, &U, &variance);
  if (k == 0) return false;
  const MeasVector r = U.transpose() * lin->residual;
  const MeasJacobian H = U.transpose() * lin->H;
  lin->m = k;
  lin->residual = r;
  lin->H = H;
  lin->R = variance.asDiagonal();
  return true;
}

}  // namespace

int findCloneSlot(const FilterState& s, std::uint32_t clone_id) {
  for (int i = 0; i < s.n_clones; ++i) {
    if (s.clones[static_cast<std::size_t>(i)].id == clone_id) return i;
  }
  return -1;
}

bool linearizeRelativePose(const FilterState& s, const RelativePoseMeasurement& m, Linearization* out) {
  const int slot = findCloneSlot(s, m.clone_id);
  if (slot < 0) return false;
  const PoseClone& a = s.clones[static_cast<std::size_t>(slot)];
  const int oa = es::cloneOffset(slot);
  const Eigen::Matrix3d Ra = a.q_odom_robot.toRotationMatrix();
  const Eigen::Matrix3d Rb = s.x.q_odom_robot.toRotationMatrix();
  const Eigen::Matrix3d Rm = m.q_robota_robotb.normalized().toRotationMatrix();
  const Eigen::Vector3d r_theta = logSo3(Rb.transpose() * Ra * Rm);
  const Eigen::Matrix3d J = leftJacobianInverseSo3(r_theta) * Rb.transpose();
  const int rows = m.has_translation ? 6 : 3;
  const int rot = rows - 3;  // first rotation row
  out->reset(rows, s.dim());
  if (m.has_translation) {
    const Eigen::Vector3d d = s.x.p_robot_in_odom_m - a.p_robot_in_odom_m;
    out->residual.head<3>() = m.p_robotb_in_robota_m - Ra.transpose() * d;
    out->H.block<3, 3>(0, oa) = -Ra.transpose();
    out->H.block<3, 3>(0, es::kP) = Ra.transpose();
    out->H.block<3, 3>(0, oa + 3) = Ra.transpose() * skew(d);
  }
  out->residual.segment<3>(rot) = r_theta;
  out->H.block<3, 3>(rot, oa + 3) = -J;
  out->H.block<3, 3>(rot, es::kTheta) = J;
  out->R = m.cov.block(6 - rows, 6 - rows, rows, rows);
  return projectOnConstrained(out);
}

}  // namespace deepnav
