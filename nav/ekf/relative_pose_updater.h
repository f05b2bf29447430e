#pragma once
#include "nav/ekf/ekf_measurements.h"
#include "nav/ekf/filter_state.h"
#include "nav/ekf/measurement_update.h"

namespace deepnav {

// A relative pose may constrain only part of the 6 DoF (plane VO: one plane pins its normal's translation
// and two rotation axes; two planes the translation in their span and the rotation). Its covariance then
// holds at least this variance (m^2, rad^2) along the directions it does not measure; the updater keeps
// only the directions below it (a pose known to 10 m or 10 rad is no measurement).
constexpr double kRelativePoseUnconstrainedVariance = 100.0;

// Constrained subspace of a measurement covariance: the eigenvectors of cov (rows x rows) whose variance
// is below kRelativePoseUnconstrainedVariance, as the columns of basis (rows x k, orthonormal), their
// variances in variance (k). Returns k (rows when every direction is constrained).
int relativePoseConstrainedBasis(const MeasMatrix& cov, MeasMatrix* basis, MeasVector* variance);

// Finite, unit-norm quaternion; the used covariance block finite, symmetric, positive definite.
bool isValidRelativePose(const RelativePoseMeasurement& m);

// Index of the clone with this id among s.clones[0, n_clones), or -1.
int findCloneSlot(const FilterState& s, std::uint32_t clone_id);

// Relative pose between clone a (slot) and the current state b:
//   rotation:    r = Log(R_b^T R_a R_m)     ~= r0 + Jl^-1(r0) R_b^T (dtheta_a - dtheta_b)
//   translation: r = p_m - R_a^T (p_b - p_a), d = p_b - p_a,
//                R_a^T d ~= R_a^T d + R_a^T (dp_b - dp_a) + R_a^T [d]x dtheta_a
// so H_theta_a = -Jl^-1 R_b^T, H_theta_b = Jl^-1 R_b^T, H_p_a = -R_a^T, H_p_b = R_a^T,
// H_theta_a(transl) = R_a^T [d]x. Rows: [translation (if any); rotation]. False when the clone is unknown.
// A measurement that constrains only a subspace (relativePoseConstrainedBasis: k < rows) is projected
// on it: residual U^T r, Jacobian U^T H, noise U^T R U = diag(variance) (k rows), so the directions the
// sensor did not observe neither move the state nor enter the gate. False when k = 0.
bool linearizeRelativePose(const FilterState& s, const RelativePoseMeasurement& m, Linearization* out);

}  // namespace deepnav
