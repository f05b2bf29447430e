#include "nav/markers/quaternion_average.h"

#include <Eigen/Eigenvalues>

namespace deepnav {

void QuaternionAverage::clear() {
  M_.setZero();
  weight_sum_ = 0.0;
  count_ = 0;
}

void QuaternionAverage::add(const Eigen::Quaterniond& q, double weight) {
  const Eigen::Vector4d v = q.normalized().coeffs();
  M_.noalias() += weight * v * v.transpose();
  weight_sum_ += weight;
  ++count_;
}

Eigen::Quaterniond QuaternionAverage::mean() const {
  if (count_ == 0 || !(weight_sum_ > 0.0)) return Eigen::Quaterniond::Identity();
  // Eigenvalues ascending: the last eigenvector is the mean (Markley et al.).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(M_);
  const Eigen::Vector4d v = solver.eigenvectors().col(3);
  Eigen::Quaterniond q(v(3), v(0), v(1), v(2));
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  return q.normalized();
}

Eigen::Matrix3d QuaternionAverage::scatter() const {
  if (count_ == 0 || !(weight_sum_ > 0.0)) return Eigen::Matrix3d::Zero();
  const Eigen::Quaterniond q_mean = mean();
  Eigen::Matrix<double, 4, 3> B;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(k);
    B.col(k) = (Eigen::Quaterniond(0.0, e.x(), e.y(), e.z()) * q_mean).coeffs();
  }
  return 4.0 * B.transpose() * (M_ / weight_sum_) * B;
}

}  // namespace deepnav
