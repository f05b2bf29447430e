#include "nav/metrics/nees.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

namespace deepnav {

double positionNees(const Eigen::Vector3d& p_est_m, const Eigen::Vector3d& p_true_m, const Eigen::Matrix3d& P_m2) {
  const Eigen::LLT<Eigen::Matrix3d> llt(P_m2);
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Vector3d e = p_est_m - p_true_m;
  return e.dot(llt.solve(e));
}

double headingError(const Eigen::Quaterniond& q_est, const Eigen::Quaterniond& q_true) {
  const Eigen::AngleAxisd d(q_true.normalized() * q_est.normalized().conjugate());
  return (d.angle() * d.axis()).z();
}

double headingNees(const Eigen::Quaterniond& q_est, const Eigen::Quaterniond& q_true, double var_yaw_rad2) {
  if (!(var_yaw_rad2 > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double e = headingError(q_est, q_true);
  return e * e / var_yaw_rad2;
}

NeesSummary summarizeNees(std::span<const double> nees, int dof, double alpha) {
  NeesSummary s;
  s.dof = dof;
  s.band = chiSquareBand(dof, alpha);
  std::vector<double> finite;
  finite.reserve(nees.size());
  for (double v : nees) {
    if (std::isfinite(v)) finite.push_back(v);
  }
  s.count = finite.size();
  if (finite.empty()) return s;
  std::size_t inside = 0, above = 0, below = 0;
  double sum = 0.0;
  for (double v : finite) {
    sum += v;
    if (v > s.band.hi) {
      ++above;
    } else if (v < s.band.lo) {
      ++below;
    } else {
      ++inside;
    }
  }
  const double n = static_cast<double>(finite.size());
  s.mean = sum / n;
  std::nth_element(finite.begin(), finite.begin() + static_cast<std::ptrdiff_t>(finite.size() / 2), finite.end());
  s.median = finite[finite.size() / 2];
  s.mean_band = chiSquareMeanBand(dof, n, alpha);
  s.in_band_fraction = static_cast<double>(inside) / n;
  s.above_fraction = static_cast<double>(above) / n;
  s.below_fraction = static_cast<double>(below) / n;
  return s;
}

}  // namespace deepnav
