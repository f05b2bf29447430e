#pragma once
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

  // Sizes the three blocks for an m-dimensional measurement on a state of dimension n, all zero.
  void reset(int m_dim, int n_dim);
};

struct UpdateOutcome {
  bool accepted = false;
  double test_ratio = 0.0;
};

// S = H P H^T + R; gate (innovation_gate.h); if accepted:
//   K = P H^T S^-1,  P+ = (I - K H) P (I - K H)^T + K R K^T  (Joseph form, Bucy & Joseph 1968),
// evaluated without forming I - K H:  B = P - K (H P),  P+ = B + (K R - B H^T) K^T,
// then dx = K residual is injected into the nominal state (filter_state.h). The attitude reset
// Jacobian (Sola 2017 eq. 287) is taken as identity, as OpenVINS and PX4 do.
UpdateOutcome gateAndUpdate(const Linearization& lin, const GateThresholds& gate, FilterState* s);

}  // namespace deepnav
