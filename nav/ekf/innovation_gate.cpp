#include "nav/ekf/innovation_gate.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace deepnav {

double chiSquareTail(int dof, double x) {
  if (x <= 0.0) return 1.0;
  const double h = 0.5 * x;
  const double e = std::exp(-h);
  if (dof % 2 == 0) {
    // Q(m, h) = e^-h sum_{i<m} h^i / i!
    double term = 1.0, sum = 1.0;
    for (int i = 1; i < dof / 2; ++i) {
      term *= h / i;
      sum += term;
    }
    return e * sum;
  }
  // Q(m + 1/2, h) = erfc(sqrt h) + e^-h sum_{i<m} h^(i+1/2) / Gamma(i + 3/2)
  double sum = 0.0;
  double term = std::sqrt(h) / (0.5 * std::sqrt(std::numbers::pi));  // h^(1/2) / Gamma(3/2)
  for (int i = 0; i < dof / 2; ++i) {
    sum += term;
    term *= h / (i + 1.5);
  }
  return std::erfc(std::sqrt(h)) + e * sum;
}

GateThresholds makeGateThresholds(double gate_sigma) {
  GateThresholds g;
  g.gate_sigma = gate_sigma;
  const double tail = std::erfc(gate_sigma / std::numbers::sqrt2);
  g.chi2[1] = gate_sigma * gate_sigma;  // exact for one dof
  for (int k = 2; k <= es::kMaxMeasDim; ++k) {
    double lo = 0.0, hi = 1e4;
    for (int it = 0; it < 200; ++it) {
      const double mid = 0.5 * (lo + hi);
      (chiSquareTail(k, mid) > tail ? lo : hi) = mid;
    }
    g.chi2[static_cast<std::size_t>(k)] = 0.5 * (lo + hi);
  }
  return g;
}

double innovationTestRatio(const MeasVector& nu, const MeasMatrix& S, const MeasMatrix& S_inv,
                           const GateThresholds& gate) {
  const int m = static_cast<int>(nu.size());
  const double g2 = gate.gate_sigma * gate.gate_sigma;
  double ratio = nu.dot(S_inv * nu) / gate.chi2[static_cast<std::size_t>(m)];
  for (int i = 0; i < m; ++i) {
    if (!(S(i, i) > 0.0)) return std::numeric_limits<double>::infinity();
    ratio = std::max(ratio, nu(i) * nu(i) / (g2 * S(i, i)));
  }
  return std::isfinite(ratio) ? ratio : std::numeric_limits<double>::infinity();
}

}  // namespace deepnav
