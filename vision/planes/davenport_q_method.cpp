#include "vision/planes/davenport_q_method.h"

#include <Eigen/Eigenvalues>

namespace deepnav {
namespace {

// Shuster's attitude matrix A(q) equals the Hamilton rotation of the conjugate quaternion: with
// components (x, y, z, w) the Hamilton quaternion is (-x, -y, -z, w).
Eigen::Vector4d shusterToHamilton(const Eigen::Vector4d& q_xyzw) {
  return Eigen::Vector4d(-q_xyzw(0), -q_xyzw(1), -q_xyzw(2), q_xyzw(3));
}

// d/dq of delta = 2 vec(q_hat^* (x) q) for q in (x, y, z, w) order: 2 [w_hat I - [v_hat]x, -v_hat].
Eigen::Matrix<double, 3, 4> rotvecJacobian(const Eigen::Quaterniond& q_hat) {
  const Eigen::Vector3d v = q_hat.vec();
  Eigen::Matrix3d vx;
  vx << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  Eigen::Matrix<double, 3, 4> L;
  L.leftCols<3>() = q_hat.w() * Eigen::Matrix3d::Identity() - vx;
  L.col(3) = -v;
  return 2.0 * L;
}

}  // namespace

bool davenportQMethod(const Eigen::Vector3d* v_a, const Eigen::Vector3d* v_b, const double* w,
                      int count, double unobservable_variance, QMethodResult* result) {
  if (count < 1 || result == nullptr) return false;
  Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
  Eigen::Vector3d z = Eigen::Vector3d::Zero();
  double w_sum = 0.0;
  for (int i = 0; i < count; ++i) {
    B += w[i] * v_a[i] * v_b[i].transpose();
    z += w[i] * v_a[i].cross(v_b[i]);
    w_sum += w[i];
  }
  if (!(w_sum > 0.0)) return false;
  const double sigma = B.trace();
  Eigen::Matrix4d K;
  K.topLeftCorner<3, 3>() = B + B.transpose() - sigma * Eigen::Matrix3d::Identity();
  K.topRightCorner<3, 1>() = z;
  K.bottomLeftCorner<1, 3>() = z.transpose();
  K(3, 3) = sigma;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eig(K);
  if (eig.info() != Eigen::Success) return false;
  const double mu = eig.eigenvalues()(3);
  const Eigen::Vector4d q = shusterToHamilton(eig.eigenvectors().col(3));
  Eigen::Quaterniond q_hat(q(3), q(0), q(1), q(2));
  q_hat.normalize();
  if (q_hat.w() < 0.0) q_hat.coeffs() = -q_hat.coeffs();

  // C_q = sum_k v_k v_k^T / (2 (mu - mu_k)) over the other eigenvectors; a gap that is zero
  // relative to the total weight is a rotation the vectors do not see.
  const Eigen::Matrix<double, 3, 4> J = rotvecJacobian(q_hat);
  const double gap_min = 1e-9 * w_sum;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  int observable = 0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d g = J * shusterToHamilton(eig.eigenvectors().col(k));
    const double gap = mu - eig.eigenvalues()(k);
    if (gap > gap_min) {
      cov += g * g.transpose() / (2.0 * gap);
      ++observable;
    } else {
      cov += unobservable_variance * g * g.transpose() / g.squaredNorm();
    }
  }
  result->q_a_b = q_hat;
  result->cov_rotvec_rad2 = 0.5 * (cov + cov.transpose());
  result->mu_max = mu;
  result->observable_dims = observable;
  return true;
}

}  // namespace deepnav
