#include "nav/ekf/systematic_states.h"

#include <algorithm>
#include <cmath>

#include "nav/ekf/ekf_config.h"

namespace deepnav {
namespace {

constexpr double kMinSystematicVariance = 1e-18;  // a floor only: far below any prior in use

void setDiagonal(int rel, int count, double sigma, FilterState* s) {
  if (rel < 0) return;
  const int o = s->sysIndex(rel);
  for (int i = o; i < o + count; ++i) s->P(i, i) = sigma * sigma;
}

}  // namespace

SystematicLayout systematicLayout(const EkfConfig& c) {
  SystematicLayout l;
  const auto add = [&l](double sigma, int count, int* offset) {
    if (sigma <= 0.0) return;
    *offset = l.dim;
    l.dim += count;
  };
  add(c.dvl_scale_prior_sigma, 1, &l.dvl_scale);
  add(c.dvl_misalignment_prior_sigma_rad, 3, &l.dvl_misalignment);
  add(c.dvl_bias_prior_sigma_mps, 3, &l.dvl_bias);
  add(c.heading_bias_prior_sigma_rad, 1, &l.heading_bias);
  add(c.heading_deviation_prior_sigma_rad, 4, &l.heading_deviation);
  return l;
}

void resetSystematicCovariance(const EkfConfig& c, FilterState* s) {
  const int ns = s->sys_layout.dim;
  if (ns == 0) return;
  const int o = s->sysOffset();
  const int n = s->dim();
  s->P.block(o, 0, ns, n).setZero();
  s->P.block(0, o, n, ns).setZero();
  const SystematicLayout& l = s->sys_layout;
  setDiagonal(l.dvl_scale, 1, c.dvl_scale_prior_sigma, s);
  setDiagonal(l.dvl_misalignment, 3, c.dvl_misalignment_prior_sigma_rad, s);
  setDiagonal(l.dvl_bias, 3, c.dvl_bias_prior_sigma_mps, s);
  setDiagonal(l.heading_bias, 1, c.heading_bias_prior_sigma_rad, s);
  setDiagonal(l.heading_deviation, 4, c.heading_deviation_prior_sigma_rad, s);
}

void relocateSystematic(int new_offset, FilterState* s) {
  const int ns = s->sys_layout.dim;
  const int old_offset = s->sysOffset();
  if (ns == 0 || new_offset == old_offset) return;
  using SysSys = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, es::kMaxSysDim, es::kMaxSysDim>;
  using Cross = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, es::kMaxDim, es::kMaxSysDim>;
  const int keep = std::min(old_offset, new_offset);
  const SysSys S = s->P.block(old_offset, old_offset, ns, ns);
  const Cross X = s->P.block(0, old_offset, keep, ns);
  s->P.block(new_offset, new_offset, ns, ns) = S;
  s->P.block(0, new_offset, keep, ns) = X;
  s->P.block(new_offset, 0, ns, keep) = X.transpose();
}

SystematicEstimates systematicEstimates(const FilterState& s) {
  SystematicEstimates e;
  e.layout = s.sys_layout;
  e.value = s.x.sys;
  const auto sd = [&s](int rel, int k) { return rel < 0 ? 0.0 : std::sqrt(s.P(s.sysIndex(rel) + k, s.sysIndex(rel) + k)); };
  const SystematicLayout& l = s.sys_layout;
  e.sigma.dvl_scale = sd(l.dvl_scale, 0);
  for (int k = 0; k < 3; ++k) e.sigma.dvl_misalignment_rad(k) = sd(l.dvl_misalignment, k);
  for (int k = 0; k < 3; ++k) e.sigma.dvl_bias_mps(k) = sd(l.dvl_bias, k);
  e.sigma.heading_bias_rad = sd(l.heading_bias, 0);
  for (int k = 0; k < 4; ++k) e.sigma.heading_deviation_rad(k) = sd(l.heading_deviation, k);
  return e;
}

EstimatorStates estimatorStates(const FilterState& s, TimeUs t_us) {
  EstimatorStates out;
  out.t_us = t_us;
  for (int k = 0; k < 3; ++k) {
    out.gyro_bias_radps[k] = s.x.b_gyro_radps(k);
    out.gyro_bias_sigma_radps[k] = std::sqrt(s.P(es::kBg + k, es::kBg + k));
    out.accel_bias_mps2[k] = s.x.b_accel_mps2(k);
    out.accel_bias_sigma_mps2[k] = std::sqrt(s.P(es::kBa + k, es::kBa + k));
  }
  const SystematicEstimates e = systematicEstimates(s);
  out.dvl_scale_estimated = e.layout.dvl_scale >= 0;
  out.dvl_scale = e.value.dvl_scale;
  out.dvl_scale_sigma = e.sigma.dvl_scale;
  out.dvl_misalignment_estimated = e.layout.dvl_misalignment >= 0;
  out.dvl_bias_estimated = e.layout.dvl_bias >= 0;
  out.heading_bias_estimated = e.layout.heading_bias >= 0;
  out.heading_bias_rad = e.value.heading_bias_rad;
  out.heading_bias_sigma_rad = e.sigma.heading_bias_rad;
  out.heading_deviation_estimated = e.layout.heading_deviation >= 0;
  for (int k = 0; k < 3; ++k) {
    out.dvl_misalignment_rad[k] = e.value.dvl_misalignment_rad(k);
    out.dvl_misalignment_sigma_rad[k] = e.sigma.dvl_misalignment_rad(k);
    out.dvl_bias_mps[k] = e.value.dvl_bias_mps(k);
    out.dvl_bias_sigma_mps[k] = e.sigma.dvl_bias_mps(k);
  }
  for (int k = 0; k < 4; ++k) {
    out.heading_deviation_rad[k] = e.value.heading_deviation_rad(k);
    out.heading_deviation_sigma_rad[k] = e.sigma.heading_deviation_rad(k);
  }
  return out;
}

void boundSystematicVariances(FilterState* s) {
  const int o = s->sysOffset();
  for (int i = o; i < o + s->sys_layout.dim; ++i) s->P(i, i) = std::max(s->P(i, i), kMinSystematicVariance);
}

}  // namespace deepnav
