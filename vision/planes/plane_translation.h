#pragma once
#include <Eigen/Core>

namespace deepnav {

// Translation p_b_in_a from matched planes: a plane (n_b, d_b) of frame b is (n_a = R n_b,
// d_a = d_b + n_a . t) in frame a, so each match gives one linear equation n_a . t = d_a - d_b.
// Weighted least squares: A = sum n n^T / var, t = A^-1 sum n (d_a - d_b) / var, cov = A^-1.
// Observable when the normals span 3D: the smallest eigenvalue of the unweighted mean
// sum n n^T / N is at least min_eigenvalue (3 orthogonal normals: 1/3; two only: 0).
struct TranslationResult {
  Eigen::Vector3d t_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_m2 = Eigen::Matrix3d::Identity();
  double min_eigenvalue = 0.0;
  bool observable = false;
};

bool solvePlaneTranslation(const Eigen::Vector3d* n_a, const double* delta_d_m,
                           const double* var_m2, int count, double min_eigenvalue,
                           TranslationResult* result);

// The same least squares restricted to the directions the normals constrain: V = the eigenvectors
// of mean(n n^T) with eigenvalue >= min_eigenvalue (one plane: its normal; two non-parallel planes:
// their span; three spanning 3D: all), t = V (V^T A V)^-1 V^T b (no component along the others),
// cov_constrained = V (V^T A V)^-1 V^T, unconstrained = I - V V^T (the projector on the others; the
// registration puts its unobservable variance there). `dims` = columns of V.
struct TranslationSubspaceResult {
  Eigen::Vector3d t_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_constrained_m2 = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d unconstrained = Eigen::Matrix3d::Identity();
  int dims = 0;
};

bool solvePlaneTranslationSubspace(const Eigen::Vector3d* n_a, const double* delta_d_m,
                                   const double* var_m2, int count, double min_eigenvalue,
                                   TranslationSubspaceResult* result);

}  // namespace deepnav
