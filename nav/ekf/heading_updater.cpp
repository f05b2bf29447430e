#include "nav/ekf/heading_updater.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/so3.h"
#include "nav/ekf/ekf_config.h"

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

namespace {

// The compass's systematic errors (systematic_states.h), when estimated. The compass reads
// psi + e(psi), e = b + B sin psi + C cos psi + D sin 2psi + E cos 2psi, psi = pi/2 - yaw - declination,
// so the yaw it gives is yaw - e(psi): the residual gains + e(psi_hat), H_theta the factor 1 + e'(psi)
// (dpsi/dyaw = -1), and H_b = -1, H_[B C D E] = -[sin psi, cos psi, sin 2psi, cos 2psi]. A true-north
// heading (gyrocompass) has no deviation.
void addHeadingSystematic(const FilterState& s, const HeadingSample& m, const EkfConfig& c, double yaw_hat,
                          Linearization* out) {
  const SystematicLayout& l = s.sys_layout;
  double e = l.heading_bias >= 0 ? s.x.sys.heading_bias_rad : 0.0;
  if (l.heading_bias >= 0) out->H(0, s.sysIndex(l.heading_bias)) = -1.0;
  if (l.heading_deviation >= 0 && !m.is_true) {
    const double psi = std::numbers::pi / 2.0 - yaw_hat - c.magnetic_declination_rad;
    const Eigen::Vector4d basis(std::sin(psi), std::cos(psi), std::sin(2.0 * psi), std::cos(2.0 * psi));
    const Eigen::Vector4d& k = s.x.sys.heading_deviation_rad;
    e += k.dot(basis);
    const double de_dpsi = k(0) * basis(1) - k(1) * basis(0) + 2.0 * (k(2) * basis(3) - k(3) * basis(2));
    out->H.block<1, 3>(0, es::kTheta) *= 1.0 + de_dpsi;
    out->H.block<1, 4>(0, s.sysIndex(l.heading_deviation)) = -basis.transpose();
  }
  out->residual(0) = wrapPi(out->residual(0) + e);
}

}  // namespace

bool linearizeHeading(const FilterState& s, const HeadingSample& m, const EkfConfig& c, Linearization* out) {
  const Eigen::Vector3d cx = s.x.q_odom_robot.toRotationMatrix().col(0);
  const double n2 = cx.x() * cx.x() + cx.y() * cx.y();
  if (n2 < kMinHorizontalNorm2) return false;
  out->reset(1, s.dim());
  const double yaw_hat = std::atan2(cx.y(), cx.x());
  out->residual(0) = wrapPi(yawFromHeading(m, c) - yaw_hat);
  out->H(0, es::kTheta + 0) = -cx.x() * cx.z() / n2;
  out->H(0, es::kTheta + 1) = -cx.y() * cx.z() / n2;
  out->H(0, es::kTheta + 2) = 1.0;
  if (s.sys_layout.heading_bias >= 0 || s.sys_layout.heading_deviation >= 0) addHeadingSystematic(s, m, c, yaw_hat, out);
  const double sample_sigma = m.sigma_rad > 0.0 ? m.sigma_rad : c.heading_sigma_rad;
  const double sigma = std::max(sample_sigma, c.heading_sigma_floor_rad);
  out->R(0, 0) = sigma * sigma;
  return true;
}

}  // namespace deepnav
