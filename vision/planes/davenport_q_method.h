#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav {

// Rotation R_a_b (q_a_b) best aligning unit vectors v_a[i] ~ R_a_b v_b[i] with weights w[i]
// (Wahba's problem) by Davenport's q-method: maximise q^T K q with
//   B = sum w v_a v_b^T,  K = [ B + B^T - tr(B) I   z ]   z = sum w v_a x v_b
//                             [ z^T                 tr(B) ],
// q = eigenvector of the largest eigenvalue mu_max (Shuster's quaternion convention, converted
// to Hamilton here). With w_i = 1 / sigma_i^2 (sigma_i^2 the per-axis variance of v_a - R v_b),
// q^T K q is the log-likelihood up to a constant, so the quaternion covariance is
// C_q = -(2 (K - mu_max I))^+ (Pathak et al., IEEE T-RO 2010). It is returned as the covariance of
// the rotation vector delta of the right perturbation R = R_hat Exp(delta) (about b's axes):
// delta = 2 vec(q_hat^* (x) q). Directions the vectors do not constrain (all v parallel: rotation
// about them) get unobservable_variance; `observable_dims` counts the others.
struct QMethodResult {
  Eigen::Quaterniond q_a_b = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d cov_rotvec_rad2 = Eigen::Matrix3d::Identity();
  double mu_max = 0.0;
  int observable_dims = 0;
};

bool davenportQMethod(const Eigen::Vector3d* v_a, const Eigen::Vector3d* v_b, const double* w,
                      int count, double unobservable_variance, QMethodResult* result);

}  // namespace deepnav
