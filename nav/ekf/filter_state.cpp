#include "nav/ekf/filter_state.h"

#include <cmath>

#include "base/so3.h"

namespace deepnav {
namespace {

void injectSystematic(const ErrorVector& dx, FilterState* s) {
  const SystematicLayout& l = s->sys_layout;
  SystematicErrors& e = s->x.sys;
  if (l.dvl_scale >= 0) e.dvl_scale += dx(s->sysIndex(l.dvl_scale));
  if (l.dvl_misalignment >= 0) e.dvl_misalignment_rad += dx.segment<3>(s->sysIndex(l.dvl_misalignment));
  if (l.dvl_bias >= 0) e.dvl_bias_mps += dx.segment<3>(s->sysIndex(l.dvl_bias));
  if (l.heading_bias >= 0) e.heading_bias_rad += dx(s->sysIndex(l.heading_bias));
  if (l.heading_deviation >= 0) e.heading_deviation_rad += dx.segment<4>(s->sysIndex(l.heading_deviation));
}

}  // namespace

void copyFilterState(const FilterState& src, FilterState* dst) {
  dst->t_us = src.t_us;
  dst->x = src.x;
  dst->clones = src.clones;
  dst->n_clones = src.n_clones;
  dst->w_robot_meas_radps = src.w_robot_meas_radps;
  dst->has_imu = src.has_imu;
  dst->sys_layout = src.sys_layout;
  dst->last_pose_fused_t_us = src.last_pose_fused_t_us;
  const int n = src.dim();
  dst->P.topLeftCorner(n, n) = src.P.topLeftCorner(n, n);
}

NominalState retractNominal(const NominalState& x, const Eigen::Matrix<double, es::kCoreDim, 1>& dx) {
  NominalState out = x;
  out.p_robot_in_odom_m += dx.segment<3>(es::kP);
  out.v_robot_in_odom_mps += dx.segment<3>(es::kV);
  out.q_odom_robot = (expSo3Quat(dx.segment<3>(es::kTheta)) * x.q_odom_robot).normalized();
  out.b_gyro_radps += dx.segment<3>(es::kBg);
  out.b_accel_mps2 += dx.segment<3>(es::kBa);
  return out;
}

void injectErrorState(const ErrorVector& dx, FilterState* s) {
  s->x = retractNominal(s->x, dx.head<es::kCoreDim>());
  for (int i = 0; i < s->n_clones; ++i) {
    const int o = es::cloneOffset(i);
    PoseClone& c = s->clones[static_cast<std::size_t>(i)];
    c.p_robot_in_odom_m += dx.segment<3>(o);
    c.q_odom_robot = (expSo3Quat(dx.segment<3>(o + 3)) * c.q_odom_robot).normalized();
  }
  if (s->sys_layout.dim > 0) injectSystematic(dx, s);
}


bool isFiniteState(const FilterState& s) {
  if (!s.x.p_robot_in_odom_m.allFinite() || !s.x.v_robot_in_odom_mps.allFinite() ||
      !s.x.q_odom_robot.coeffs().allFinite() || !s.x.b_gyro_radps.allFinite() || !s.x.b_accel_mps2.allFinite() ||
      !std::isfinite(s.x.sys.dvl_scale + s.x.sys.dvl_misalignment_rad.sum() + s.x.sys.dvl_bias_mps.sum() +
                     s.x.sys.heading_bias_rad +
                     s.x.sys.heading_deviation_rad.sum())) {
    return false;
  }
  for (int i = 0; i < s.n_clones; ++i) {
    const PoseClone& c = s.clones[static_cast<std::size_t>(i)];
    if (!c.p_robot_in_odom_m.allFinite() || !c.q_odom_robot.coeffs().allFinite()) return false;
  }
  // NaN and Inf survive a sum (Inf - Inf = NaN): one pass instead of a test per entry. A finite sum can
  // only overflow for entries near 1e308, which would be a broken covariance anyway.
  const int n = s.dim();
  return std::isfinite(s.P.topLeftCorner(n, n).sum());
}

}  // namespace deepnav
