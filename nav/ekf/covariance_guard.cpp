#include "nav/ekf/covariance_guard.h"

#include <algorithm>
#include <cmath>

#include "nav/ekf/ekf_config.h"
#include "nav/ekf/systematic_states.h"

namespace deepnav {
namespace {

void boundOne(int i, double lo, double hi, FilterState* s) {
  const int n = s->dim();
  const double v = s->P(i, i);
  if (v > hi) {
    const double k = std::sqrt(hi / v);
    s->P.row(i).head(n) *= k;
    s->P.col(i).head(n) *= k;
    s->P(i, i) = hi;  // exact, despite rounding of k * k
  } else if (v < lo) {
    s->P(i, i) = lo;
  }
}

void boundBlock(int offset, double lo, double hi, FilterState* s) {
  for (int i = offset; i < offset + 3; ++i) boundOne(i, lo, hi, s);
}

}  // namespace

VarianceBounds varianceBoundsFrom(const EkfConfig& c) {
  VarianceBounds b;
  b.pos_min = c.pos_var_min_m2;
  b.pos_max = c.pos_var_max_m2;
  b.vel_min = c.vel_var_min_m2ps2;
  b.vel_max = c.vel_var_max_m2ps2;
  b.angle_min = c.angle_var_min_rad2;
  b.angle_max = c.angle_var_max_rad2;
  b.gyro_bias_min = c.gyro_bias_var_min_rad2ps2;
  b.gyro_bias_max = c.gyro_bias_var_max_rad2ps2;
  b.accel_bias_min = c.accel_bias_var_min_m2ps4;
  b.accel_bias_max = c.accel_bias_var_max_m2ps4;
  return b;
}

bool conditionCovariance(const VarianceBounds& b, FilterState* s, int sym_dim) {
  const int n = s->dim();
  auto P = s->P.topLeftCorner(n, n);
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(P(i, i)) || P(i, i) <= 0.0) return false;
  }
  // Symmetrise in place: upper triangle := mean, lower := copy (no temporary).
  const int m = std::min(n, sym_dim);
  for (int c = 1; c < n; ++c) {
    for (int r = 0; r < std::min(c, m); ++r) {
      const double m = 0.5 * (P(r, c) + P(c, r));
      P(r, c) = m;
      P(c, r) = m;
    }
  }
  boundBlock(es::kP, b.pos_min, b.pos_max, s);
  boundBlock(es::kV, b.vel_min, b.vel_max, s);
  boundBlock(es::kTheta, b.angle_min, b.angle_max, s);
  boundBlock(es::kBg, b.gyro_bias_min, b.gyro_bias_max, s);
  boundBlock(es::kBa, b.accel_bias_min, b.accel_bias_max, s);
  for (int k = 0; k < s->n_clones; ++k) {
    boundBlock(es::cloneOffset(k), b.pos_min, b.pos_max, s);
    boundBlock(es::cloneOffset(k) + 3, b.angle_min, b.angle_max, s);
  }
  boundSystematicVariances(s);
  return true;
}

void resetCovariance(const EkfConfig& c, FilterState* s) {
  s->n_clones = 0;
  s->P.topLeftCorner<es::kCoreDim, es::kCoreDim>().setZero();
  auto d = s->P.topLeftCorner<es::kCoreDim, es::kCoreDim>().diagonal();
  d.segment<3>(es::kP).setConstant(c.init_pos_sigma_m * c.init_pos_sigma_m);
  d.segment<3>(es::kV).setConstant(c.init_vel_sigma_mps * c.init_vel_sigma_mps);
  d.segment<2>(es::kTheta).setConstant(c.init_roll_pitch_sigma_rad * c.init_roll_pitch_sigma_rad);
  d(es::kTheta + 2) = c.init_yaw_sigma_rad * c.init_yaw_sigma_rad;
  d.segment<3>(es::kBg).setConstant(c.init_gyro_bias_sigma_radps * c.init_gyro_bias_sigma_radps);
  d.segment<3>(es::kBa).setConstant(c.init_accel_bias_sigma_mps2 * c.init_accel_bias_sigma_mps2);
  s->sys_layout = systematicLayout(c);
  resetSystematicCovariance(c, s);
}

}  // namespace deepnav
