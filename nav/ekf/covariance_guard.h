#pragma once
#include "nav/ekf/filter_state.h"

namespace deepnav {

struct EkfConfig;

// Variance bounds per error-state group (the clones use the position and angle bounds).
struct VarianceBounds {
  double pos_min = 0.0, pos_max = 0.0;
  double vel_min = 0.0, vel_max = 0.0;
  double angle_min = 0.0, angle_max = 0.0;
  double gyro_bias_min = 0.0, gyro_bias_max = 0.0;
  double accel_bias_min = 0.0, accel_bias_max = 0.0;
};

VarianceBounds varianceBoundsFrom(const EkfConfig& config);

// Keeps the used block of P symmetric, (P + P^T) / 2, and its variances inside the bounds without
// breaking positive semi-definiteness: a variance above max scales its row and column by
// sqrt(max / P_ii) (a congruence D P D), one below min gets (min - P_ii) added on the diagonal (adding
// a PSD matrix). Returns false when a diagonal entry is non-finite or not positive, so the caller resets.
// Only the first sym_dim rows and columns are symmetrised: after a propagation only the core block can
// have lost symmetry (the cross blocks are written as X and X^T, the clone block is untouched), so the
// propagation passes es::kCoreDim; an update passes s->dim() (the default).
bool conditionCovariance(const VarianceBounds& bounds, FilterState* s, int sym_dim = es::kMaxDim);

// Initial covariance of the core state (diagonal, from the config sigmas) and of the systematic states
// the config enables (systematic_states.h); clones are dropped.
void resetCovariance(const EkfConfig& config, FilterState* s);

}  // namespace deepnav
