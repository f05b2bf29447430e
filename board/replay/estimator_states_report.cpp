#include "board/replay/estimator_states_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace deepnav {
namespace {

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

template <class V>
std::string list(const V& v) {
  std::string s = "[";
  for (int i = 0; i < v.size(); ++i) s += (i ? ", " : "") + num(v(i));
  return s + "]";
}

std::string entry(const std::string& value, const std::string& sigma) {
  return "{\"value\": " + value + ", \"sigma\": " + sigma + "}";
}

template <class V>
std::string vectorEntry(bool on, const V& value, const V& sigma) {
  return on ? entry(list(value), list(sigma)) : std::string("null");
}

std::string scalarEntry(bool on, double value, double sigma) { return on ? entry(num(value), num(sigma)) : "null"; }

}  // namespace

EstimatorStatesReport estimatorStatesReport(const Ekf& ekf) {
  EstimatorStatesReport r;
  if (!ekf.aligned()) return r;
  const FilterState& s = ekf.state();
  r.valid = true;
  r.b_gyro_radps = s.x.b_gyro_radps;
  r.b_accel_mps2 = s.x.b_accel_mps2;
  for (int k = 0; k < 3; ++k) {
    r.b_gyro_sigma_radps(k) = std::sqrt(s.P(es::kBg + k, es::kBg + k));
    r.b_accel_sigma_mps2(k) = std::sqrt(s.P(es::kBa + k, es::kBa + k));
  }
  r.systematic = systematicEstimates(s);
  return r;
}

std::string estimatorStatesJson(const EstimatorStatesReport& r) {
  if (!r.valid) return "null";
  const SystematicLayout& l = r.systematic.layout;
  const SystematicErrors& v = r.systematic.value;
  const SystematicErrors& sd = r.systematic.sigma;
  std::ostringstream o;
  o << "{\"gyro_bias_radps\": " << entry(list(r.b_gyro_radps), list(r.b_gyro_sigma_radps))
    << ", \"accel_bias_mps2\": " << entry(list(r.b_accel_mps2), list(r.b_accel_sigma_mps2))
    << ", \"dvl_scale\": " << scalarEntry(l.dvl_scale >= 0, v.dvl_scale, sd.dvl_scale)
    << ", \"dvl_misalignment_rad\": "
    << vectorEntry(l.dvl_misalignment >= 0, v.dvl_misalignment_rad, sd.dvl_misalignment_rad)
    << ", \"dvl_bias_mps\": " << vectorEntry(l.dvl_bias >= 0, v.dvl_bias_mps, sd.dvl_bias_mps)
    << ", \"heading_bias_rad\": " << scalarEntry(l.heading_bias >= 0, v.heading_bias_rad, sd.heading_bias_rad)
    << ", \"heading_deviation_bcde_rad\": "
    << vectorEntry(l.heading_deviation >= 0, v.heading_deviation_rad, sd.heading_deviation_rad) << "}";
  return o.str();
}

}  // namespace deepnav
