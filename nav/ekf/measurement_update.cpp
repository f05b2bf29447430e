#include "nav/ekf/measurement_update.h"

#include <limits>

#include <Eigen/Cholesky>

namespace deepnav {

void Linearization::reset(int m_dim, int n_dim) {
  m = m_dim;
  residual.setZero(m_dim);
  H.setZero(m_dim, n_dim);
  R.setZero(m_dim, m_dim);
  consider_count = 0;
}

namespace {

// S = H P H^T + R and its inverse; fills the outcome's innovation, diag S and test ratio. False (ratio
// infinite) when S is not positive definite or not finite.
bool gateMeasurement(const Linearization& lin, const GateThresholds& gate, const FilterState& s, MeasJacobian* HP,
                     MeasMatrix* S_inv, UpdateOutcome* out) {
  const int n = s.dim();
  const int m = lin.m;
  HP->noalias() = lin.H * s.P.topLeftCorner(n, n);
  MeasMatrix S(m, m);
  S.noalias() = *HP * lin.H.transpose();
  S += lin.R;
  out->m = m;
  for (int i = 0; i < m; ++i) {
    out->innovation[static_cast<std::size_t>(i)] = lin.residual(i);
    out->innovation_variance[static_cast<std::size_t>(i)] = S(i, i);
  }
  const Eigen::LLT<MeasMatrix> llt(S);
  if (llt.info() != Eigen::Success || !S.allFinite()) {
    out->test_ratio = std::numeric_limits<double>::infinity();
    return false;
  }
  *S_inv = llt.solve(MeasMatrix::Identity(m, m));
  out->test_ratio = innovationTestRatio(lin.residual, S, *S_inv, gate);
  return true;
}

}  // namespace

UpdateOutcome gateOnly(const Linearization& lin, const GateThresholds& gate, const FilterState& s) {
  UpdateOutcome out;
  MeasJacobian HP(lin.m, s.dim());
  MeasMatrix S_inv(lin.m, lin.m);
  gateMeasurement(lin, gate, s, &HP, &S_inv, &out);
  return out;
}

UpdateOutcome gateAndUpdate(const Linearization& lin, const GateThresholds& gate, FilterState* s) {
  UpdateOutcome out;
  const int n = s->dim();
  const int m = lin.m;
  MeasJacobian HP(m, n);
  MeasMatrix S_inv(m, m);
  if (!gateMeasurement(lin, gate, *s, &HP, &S_inv, &out) || !(out.test_ratio <= 1.0)) return out;

  auto P = s->P.topLeftCorner(n, n);
  GainMatrix K(n, m);
  K.noalias() = HP.transpose() * S_inv;
  if (lin.consider_count > 0) K.middleRows(lin.consider_begin, lin.consider_count).setZero();
  ErrorVector dx(n);
  dx.noalias() = K * lin.residual;
  P.noalias() -= K * HP;  // B
  GainMatrix C(n, m);
  C.noalias() = K * lin.R;
  C.noalias() -= P * lin.H.transpose();
  P.noalias() += C * K.transpose();
  injectErrorState(dx, s);
  out.accepted = true;
  return out;
}

}  // namespace deepnav
