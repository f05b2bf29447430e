#include "base/so3.h"

#include <cmath>
#include <numbers>

namespace deepnav {
namespace {
// Below this angle the series expansions are used: the closed forms divide by theta^2 or theta^3.
constexpr double kSmallAngleRad = 1e-6;
}  // namespace

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

Eigen::Matrix3d expSo3(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d K = skew(phi);
  if (theta < kSmallAngleRad) return Eigen::Matrix3d::Identity() + K + 0.5 * K * K;
  // Rodrigues: R = I + sin(t)/t K + (1 - cos(t))/t^2 K^2.
  return Eigen::Matrix3d::Identity() + (std::sin(theta) / theta) * K +
         ((1.0 - std::cos(theta)) / (theta * theta)) * K * K;
}

Eigen::Quaterniond expSo3Quat(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  if (theta < kSmallAngleRad) {
    Eigen::Quaterniond q(1.0, 0.5 * phi.x(), 0.5 * phi.y(), 0.5 * phi.z());
    return q.normalized();
  }
  const Eigen::Vector3d axis = phi / theta;
  const double s = std::sin(0.5 * theta);
  return Eigen::Quaterniond(std::cos(0.5 * theta), s * axis.x(), s * axis.y(), s * axis.z());
}

Eigen::Vector3d logSo3(const Eigen::Matrix3d& R) {
  // Through the quaternion: robust near 0 and near pi, unlike acos((tr R - 1) / 2).
  Eigen::Quaterniond q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const Eigen::Vector3d u = q.vec();
  const double s = u.norm();
  if (s < kSmallAngleRad) return 2.0 * u / q.w();
  return (2.0 * std::atan2(s, q.w()) / s) * u;
}

Eigen::Matrix3d rightJacobianSo3(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d K = skew(phi);
  if (theta < kSmallAngleRad) return Eigen::Matrix3d::Identity() - 0.5 * K + K * K / 6.0;
  const double t2 = theta * theta;
  return Eigen::Matrix3d::Identity() - ((1.0 - std::cos(theta)) / t2) * K +
         ((theta - std::sin(theta)) / (t2 * theta)) * K * K;
}

Eigen::Matrix3d rightJacobianInverseSo3(const Eigen::Vector3d& phi) {
  const double theta = phi.norm();
  const Eigen::Matrix3d K = skew(phi);
  if (theta < kSmallAngleRad) return Eigen::Matrix3d::Identity() + 0.5 * K + K * K / 12.0;
  const double t2 = theta * theta;
  const double sin_theta = std::sin(theta);
  // At theta = pi the inverse does not exist; callers gate such residuals away, keep the value finite.
  if (sin_theta < kSmallAngleRad) return Eigen::Matrix3d::Identity() + 0.5 * K + K * K / t2;
  const double c = 1.0 / t2 - (1.0 + std::cos(theta)) / (2.0 * theta * sin_theta);
  return Eigen::Matrix3d::Identity() + 0.5 * K + c * K * K;
}

Eigen::Matrix3d leftJacobianInverseSo3(const Eigen::Vector3d& phi) { return rightJacobianInverseSo3(-phi); }

double wrapPi(double angle_rad) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double a = std::fmod(angle_rad + std::numbers::pi, kTwoPi);
  if (a < 0.0) a += kTwoPi;
  return a - std::numbers::pi;
}

}  // namespace deepnav
