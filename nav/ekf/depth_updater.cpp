#include "nav/ekf/depth_updater.h"

#include <cmath>

#include "base/so3.h"
#include "nav/ekf/ekf_config.h"

namespace deepnav {

bool isValidDepth(const DepthSample& m) {
  return std::isfinite(m.depth_m) && std::isfinite(m.sigma_m) && m.sigma_m >= 0.0;
}

bool linearizeDepth(const FilterState& s, const DepthSample& m, const EkfConfig& c, Linearization* out) {
  const Eigen::Vector3d Rr = s.x.q_odom_robot * c.p_depth_in_robot_m;
  const double depth_pred = -(s.x.p_robot_in_odom_m.z() + Rr.z());
  out->reset(1, s.dim());
  out->residual(0) = m.depth_m - depth_pred;
  out->H(0, es::kP + 2) = -1.0;
  out->H.block<1, 3>(0, es::kTheta) = skew(Rr).row(2);
  const double sigma = m.sigma_m > 0.0 ? m.sigma_m : c.depth_sigma_m;
  out->R(0, 0) = sigma * sigma;
  return true;
}

}  // namespace deepnav
