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

}  // namespace deepnav
