#include "nav/metrics/smoothness.h"

#include <vector>

namespace deepnav {

bool lagOneAutocorrelation(std::span<const double> d, double* num_out, double* den_out) {
  if (d.size() < 2) return false;
  double mean = 0.0;
  for (double x : d) mean += x;
  mean /= static_cast<double>(d.size());
  double num = 0.0, den = 0.0;
  for (std::size_t k = 0; k < d.size(); ++k) {
    den += (d[k] - mean) * (d[k] - mean);
    if (k + 1 < d.size()) num += (d[k] - mean) * (d[k + 1] - mean);
  }
  if (!(den > 0.0)) return false;
  *num_out = num;
  *den_out = den;
  return true;
}

bool lagOneAutocorrelation(std::span<const double> d, double* r1) {
  double num = 0.0, den = 0.0;
  if (!lagOneAutocorrelation(d, &num, &den)) return false;
  *r1 = num / den;
  return true;
}

Smoothness smoothnessMa(std::span<const Eigen::Vector3d> p) {
  Smoothness s;
  if (p.size() < 3) return s;
  std::vector<double> d(p.size() - 1);
  double num_sum = 0.0, den_sum = 0.0;
  for (int j = 0; j < 3; ++j) {
    for (std::size_t k = 0; k + 1 < p.size(); ++k) d[k] = p[k + 1](j) - p[k](j);
    double num = 0.0, den = 0.0;
    if (!lagOneAutocorrelation(d, &num, &den)) continue;
    s.r_axis(j) = num / den;
    num_sum += num;
    den_sum += den;
    ++s.axes_used;
  }
  if (s.axes_used > 0) s.m_a = num_sum / den_sum;
  return s;
}

}  // namespace deepnav
