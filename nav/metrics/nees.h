#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/metrics/chi_square.h"

namespace deepnav {

// Normalised estimation error squared (NEES) of the filter against its own covariance: consistency
// (Bar-Shalom, Li, Kirubarajan 2001, sec. 5.4.2). For a consistent estimator e^T P^-1 e is chi-square with
// as many dof as e has components, so ~95 % of the samples fall inside the two-sided 95 % band.

// Position (3 dof): e = p_est - p_true, P the 3x3 position covariance. NaN when P is not positive definite.
double positionNees(const Eigen::Vector3d& p_est_m, const Eigen::Vector3d& p_true_m, const Eigen::Matrix3d& P_m2);

// Heading (1 dof): the rotation error about the odometry z axis, dtheta = Log(R_true R_est^T) (the
// filter's left perturbation about the odom axes, R = Exp(dtheta) R_est: nav/ekf/error_state.h), its z
// component squared over the yaw variance. NaN when the variance is not positive.
double headingError(const Eigen::Quaterniond& q_est, const Eigen::Quaterniond& q_true);
double headingNees(const Eigen::Quaterniond& q_est, const Eigen::Quaterniond& q_true, double var_yaw_rad2);

// Summary of a NEES series of `dof` degrees of freedom with the two-sided (1 - alpha) bands: per sample,
// and for the mean over the N samples (valid for independent samples: successive filter epochs are
// correlated, so the mean band is narrower than the mean's real spread and is a nominal reference).
struct NeesSummary {
  int dof = 0;
  std::size_t count = 0;          // finite samples
  double mean = 0.0;
  double median = 0.0;
  ChiSquareBand band;             // per sample
  ChiSquareBand mean_band;        // for the mean over count samples
  double in_band_fraction = 0.0;  // share of samples inside `band` (0.95 expected)
  double above_fraction = 0.0;    // share above band.hi (overconfident filter)
  double below_fraction = 0.0;    // share below band.lo (pessimistic filter)
};
NeesSummary summarizeNees(std::span<const double> nees, int dof, double alpha = 0.05);

}  // namespace deepnav
