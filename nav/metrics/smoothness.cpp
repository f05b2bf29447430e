#include "nav/metrics/smoothness.h"

#include <vector>

namespace deepnav {

bool lagOneAutocorrelation(std::span<const double> d, double* r1) {
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
  *r1 = num / den;
  return true;
}

Smoothness smoothnessMa(std::span<const Eigen::Vector3d> p) {
  Smoothness s;
  if (p.size() < 3) return s;
  std::vector<double> d(p.size() - 1);
  double sum = 0.0;
  for (int j = 0; j < 3; ++j) {
    for (std::size_t k = 0; k + 1 < p.size(); ++k) d[k] = p[k + 1](j) - p[k](j);
    double r1 = 0.0;
    if (!lagOneAutocorrelation(d, &r1)) continue;
    sum += r1;
    ++s.axes_used;
  }
  if (s.axes_used > 0) s.m_a = sum / s.axes_used;
  return s;
}

}  // namespace deepnav
