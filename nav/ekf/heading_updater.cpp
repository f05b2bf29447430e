#include "nav/ekf/heading_updater.h"

#include <cmath>
#include <numbers>

#include "nav/ekf/ekf_config.h"
#include "nav/ekf/so3.h"

namespace deepnav {
namespace {
constexpr double kMinHorizontalNorm2 = 1e-6;  // |c_xy|^2 below this: pitch within ~0.06 deg of vertical
}

bool isValidHeading(const HeadingSample& m) {
  return std::isfinite(m.heading_rad) && std::isfinite(m.sigma_rad) && m.sigma_rad >= 0.0;
}

double yawFromHeading(const HeadingSample& m, const EkfConfig& c) {
  const double declination = m.is_true ? 0.0 : c.magnetic_declination_rad;
  return wrapPi(std::numbers::pi / 2.0 - (m.heading_rad + declination - c.heading_bias_rad));
}

bool linearizeHeading(const FilterState& s, const HeadingSample& m, const EkfConfig& c, Linearization* out) {
  const Eigen::Vector3d cx = s.x.q_odom_robot.toRotationMatrix().col(0);
  const double n2 = cx.x() * cx.x() + cx.y() * cx.y();
  if (n2 < kMinHorizontalNorm2) return false;
  out->reset(1, s.dim());
  out->residual(0) = wrapPi(yawFromHeading(m, c) - std::atan2(cx.y(), cx.x()));
  out->H(0, es::kTheta + 0) = -cx.x() * cx.z() / n2;
  out->H(0, es::kTheta + 1) = -cx.y() * cx.z() / n2;
  out->H(0, es::kTheta + 2) = 1.0;
  const double sigma = m.sigma_rad > 0.0 ? m.sigma_rad : c.heading_sigma_rad;
  out->R(0, 0) = sigma * sigma;
  return true;
}

}  // namespace deepnav
