#include "nav/ekf/filter_state.h"

#include <cmath>

#include "nav/ekf/so3.h"

namespace deepnav {

void copyFilterState(const FilterState& src, FilterState* dst) {
  dst->t_us = src.t_us;
  dst->x = src.x;
  dst->clones = src.clones;
  dst->n_clones = src.n_clones;
  dst->w_robot_meas_radps = src.w_robot_meas_radps;
  dst->has_imu = src.has_imu;
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
}

bool isFiniteState(const FilterState& s) {
  if (!s.x.p_robot_in_odom_m.allFinite() || !s.x.v_robot_in_odom_mps.allFinite() ||
      !s.x.q_odom_robot.coeffs().allFinite() || !s.x.b_gyro_radps.allFinite() || !s.x.b_accel_mps2.allFinite()) {
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
