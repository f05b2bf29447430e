#include "nav/ekf/attitude_updater.h"

#include <cmath>

#include "base/so3.h"
#include "nav/ekf/ekf_config.h"

namespace deepnav {
namespace {
constexpr double kMinCosPitch = 1e-3;
}

bool isValidAttitude(const AttitudeSample& m) {
  return std::isfinite(m.roll_rad) && std::isfinite(m.pitch_rad) && std::isfinite(m.sigma_rad) && m.sigma_rad >= 0.0;
}

bool linearizeAttitude(const FilterState& s, const AttitudeSample& m, const EkfConfig& c, Linearization* out) {
  const Eigen::Matrix3d R = s.x.q_odom_robot.toRotationMatrix();
  const double cos_pitch2 = R(2, 1) * R(2, 1) + R(2, 2) * R(2, 2);
  if (cos_pitch2 < kMinCosPitch * kMinCosPitch) return false;
  const double cos_pitch = std::sqrt(cos_pitch2);
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double pitch = std::atan2(-R(2, 0), cos_pitch);
  out->reset(2, s.dim());
  out->residual(0) = wrapPi(m.roll_rad - roll);
  out->residual(1) = wrapPi(m.pitch_rad - pitch);
  out->H(0, es::kTheta + 0) = (R(2, 2) * R(1, 1) - R(2, 1) * R(1, 2)) / cos_pitch2;
  out->H(0, es::kTheta + 1) = (R(2, 1) * R(0, 2) - R(2, 2) * R(0, 1)) / cos_pitch2;
  out->H(1, es::kTheta + 0) = -R(1, 0) / cos_pitch;
  out->H(1, es::kTheta + 1) = R(0, 0) / cos_pitch;
  const double sigma = m.sigma_rad > 0.0 ? m.sigma_rad : c.attitude_sigma_rad;
  out->R = MeasMatrix::Identity(2, 2) * (sigma * sigma);
  return true;
}

}  // namespace deepnav
