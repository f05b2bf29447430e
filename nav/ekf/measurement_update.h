#pragma once
#include <array>

#include "nav/ekf/error_state.h"
#include "nav/ekf/filter_state.h"
#include "nav/ekf/innovation_gate.h"

namespace deepnav {

// A measurement linearised at the nominal state, the common currency of all updaters:
//   residual = z [-] h(x_hat)  (manifold difference for rotations),  residual ~= H dx + noise, noise ~ N(0, R).
struct Linearization {
  int m = 0;
  MeasVector residual;
  MeasJacobian H;  // m x dim()
  MeasMatrix R;    // m x m
  // Schmidt-Kalman "consider" states [consider_begin, consider_begin + consider_count): their uncertainty
  // enters S and P, but their gain rows are zeroed so the update does not correct them (systematic
  // states while nothing absolute observes them, systematic_states.h).
  int consider_begin = 0;
  int consider_count = 0;

  // Sizes the three blocks for an m-dimensional measurement on a state of dimension n, all zero.
  void reset(int m_dim, int n_dim);
};

// What the gate saw: the innovation and the diagonal of S = H P H^T + R (first m entries), for the
// per-fusion diagnostics (fusion_diagnostic.h). m = 0 when no innovation was formed.
struct UpdateOutcome {
  bool accepted = false;
  double test_ratio = 0.0;
  int m = 0;
  std::array<double, es::kMaxMeasDim> innovation{};
  std::array<double, es::kMaxMeasDim> innovation_variance{};
};

// S = H P H^T + R; gate (innovation_gate.h); if accepted:
//   K = P H^T S^-1,  P+ = (I - K H) P (I - K H)^T + K R K^T  (Joseph form, Bucy & Joseph 1968),
// evaluated without forming I - K H:  B = P - K (H P),  P+ = B + (K R - B H^T) K^T,
// then dx = K residual is injected into the nominal state (filter_state.h). The Joseph form holds for any
// gain, so zeroing the consider states' rows of K (Schmidt 1966) keeps P the covariance of the estimate. The attitude reset
// Jacobian (Sola 2017 eq. 287) is taken as identity, as OpenVINS and PX4 do.
UpdateOutcome gateAndUpdate(const Linearization& lin, const GateThresholds& gate, FilterState* s);

// The gate's view of a measurement (innovation, diag S, test ratio) without fusing it: a refused compass
// keeps being watched.
UpdateOutcome gateOnly(const Linearization& lin, const GateThresholds& gate, const FilterState& s);

}  // namespace deepnav
