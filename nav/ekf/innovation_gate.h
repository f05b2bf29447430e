#pragma once
#include <array>

#include "nav/ekf/error_state.h"

namespace deepnav {

// Innovation consistency gate, PX4 style: the test ratio is <= 1 for an acceptable innovation.
//   one dof:  ratio = nu^2 / (gate^2 S)                                    (PX4 ekf2 test ratio)
//   k dof:    ratio = max( d^2 / c_k ,  max_i nu_i^2 / (gate^2 S_ii) ),   d^2 = nu^T S^-1 nu
// where c_k is the chi-square quantile with the same tail probability as the scalar gate,
// P(chi2_k > c_k) = P(|N(0,1)| > gate) = erfc(gate / sqrt 2), so that gate 3 means 99.73 % for any k
// (c_1 = 9, c_3 = 14.2, c_6 = 20.1). The per-axis term keeps a large error on one axis from hiding in the
// k-dof sum (a 5-sigma error on one axis of a 6-dof pose would otherwise pass a 99.73 % chi-square test).
// A ratio that is non-finite (or an S that is not positive definite) rejects.
struct GateThresholds {
  double gate_sigma = 3.0;
  std::array<double, es::kMaxMeasDim + 1> chi2{};  // chi2[k] = c_k, index 0 unused
};

// Computed once at init (bisection on the closed-form chi-square tail for k <= 6).
GateThresholds makeGateThresholds(double gate_sigma);

// P(chi2_k > x) for k in [1, 6]: closed forms of the regularised upper incomplete gamma function.
double chiSquareTail(int dof, double x);

double innovationTestRatio(const MeasVector& nu, const MeasMatrix& S, const MeasMatrix& S_inv,
                           const GateThresholds& gate);

}  // namespace deepnav
