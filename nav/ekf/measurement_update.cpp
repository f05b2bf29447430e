#include "nav/ekf/measurement_update.h"

#include <limits>

#include <Eigen/Cholesky>

namespace deepnav {

void Linearization::reset(int m_dim, int n_dim) {
  m = m_dim;
  residual.setZero(m_dim);
  H.setZero(m_dim, n_dim);
  R.setZero(m_dim, m_dim);
}

UpdateOutcome gateAndUpdate(const Linearization& lin, const GateThresholds& gate, FilterState* s) {
  UpdateOutcome out;
  const int n = s->dim();
  const int m = lin.m;
  auto P = s->P.topLeftCorner(n, n);
  MeasJacobian HP(m, n);
  HP.noalias() = lin.H * P;
  MeasMatrix S(m, m);
  S.noalias() = HP * lin.H.transpose();
  S += lin.R;
  const Eigen::LLT<MeasMatrix> llt(S);
  if (llt.info() != Eigen::Success || !S.allFinite()) {
    out.test_ratio = std::numeric_limits<double>::infinity();
    return out;
  }
  const MeasMatrix S_inv = llt.solve(MeasMatrix::Identity(m, m));
  out.test_ratio = innovationTestRatio(lin.residual, S, S_inv, gate);
  if (!(out.test_ratio <= 1.0)) return out;

  GainMatrix K(n, m);
  K.noalias() = HP.transpose() * S_inv;
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
