#include "vision/planes/plane_translation.h"

#include <Eigen/Eigenvalues>

namespace deepnav {
namespace {

// Each plane i moved along its normal n_i by delta_d_i (variance var_i): n_i^T t = delta_d_i. N is the
// unweighted sum of n n^T (its eigenvalues say which directions the normals span), A and b the weighted
// normal equations A t = b.
struct NormalEquations {
  Eigen::Matrix3d N = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
};

// False without a plane or with a variance that is not positive.
bool accumulate(const Eigen::Vector3d* n_a, const double* delta_d_m, const double* var_m2, int count,
                NormalEquations* e) {
  if (count < 1) return false;
  for (int i = 0; i < count; ++i) {
    if (!(var_m2[i] > 0.0)) return false;
    e->N += n_a[i] * n_a[i].transpose();
    e->A += n_a[i] * n_a[i].transpose() / var_m2[i];
    e->b += n_a[i] * delta_d_m[i] / var_m2[i];
  }
  return true;
}

}  // namespace

bool solvePlaneTranslation(const Eigen::Vector3d* n_a, const double* delta_d_m,
                           const double* var_m2, int count, double min_eigenvalue,
                           TranslationResult* result) {
  NormalEquations e;
  if (result == nullptr || !accumulate(n_a, delta_d_m, var_m2, count, &e)) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(e.N / count, Eigen::EigenvaluesOnly);
  result->min_eigenvalue = eig.eigenvalues()(0);
  result->observable = count >= 3 && result->min_eigenvalue >= min_eigenvalue;
  if (!result->observable) return true;
  const Eigen::Matrix3d cov = e.A.inverse();
  result->t_m = cov * e.b;
  result->cov_m2 = 0.5 * (cov + cov.transpose());
  return true;
}

bool solvePlaneTranslationSubspace(const Eigen::Vector3d* n_a, const double* delta_d_m,
                                   const double* var_m2, int count, double min_eigenvalue,
                                   TranslationSubspaceResult* result) {
  NormalEquations e;
  if (result == nullptr || !accumulate(n_a, delta_d_m, var_m2, count, &e)) return false;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(e.N / count);
  // Eigenvalues ascend: the constrained directions are the last `dims`.
  int dims = 0;
  for (int i = 0; i < 3; ++i) dims += eig.eigenvalues()(i) >= min_eigenvalue ? 1 : 0;
  result->dims = dims;
  result->t_m.setZero();
  result->cov_constrained_m2.setZero();
  result->unconstrained.setIdentity();
  if (dims == 0) return true;
  const Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> V = eig.eigenvectors().rightCols(dims);
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> info = V.transpose() * e.A * V;
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, 3> cov_v = info.inverse();
  result->t_m = V * (cov_v * (V.transpose() * e.b));
  const Eigen::Matrix3d cov = V * cov_v * V.transpose();
  result->cov_constrained_m2 = 0.5 * (cov + cov.transpose());
  result->unconstrained = Eigen::Matrix3d::Identity() - V * V.transpose();
  return true;
}

}  // namespace deepnav
