#pragma once
#include <Eigen/Core>

namespace deepnav {

// Running first and second moments of a point set, relative to a fixed origin (the seed) so that
// the scatter about the mean, sum (p - m)(p - m)^T = sum q q^T - N m_q m_q^T with q = p - origin,
// does not lose its small eigenvalue to cancellation (sums of points metres away, residuals of
// millimetres).
struct ScatterSums {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double n = 0.0;
  double sx = 0.0, sy = 0.0, sz = 0.0;
  double sxx = 0.0, sxy = 0.0, sxz = 0.0, syy = 0.0, syz = 0.0, szz = 0.0;

  void reset(const Eigen::Vector3d& new_origin) {
    *this = ScatterSums{};
    origin = new_origin;
  }
  void add(double x, double y, double z) {  // x, y, z relative to origin
    n += 1.0;
    sx += x;
    sy += y;
    sz += z;
    sxx += x * x;
    sxy += x * y;
    sxz += x * z;
    syy += y * y;
    syz += y * z;
    szz += z * z;
  }
  Eigen::Vector3d meanRelative() const { return Eigen::Vector3d(sx, sy, sz) / n; }
  Eigen::Vector3d mean() const { return origin + meanRelative(); }
  // Scatter about the mean (sum, not divided by N).
  Eigen::Matrix3d scatter() const {
    const Eigen::Vector3d m = meanRelative();
    Eigen::Matrix3d s;
    s << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
    return s - n * m * m.transpose();
  }
  // sum p p^T about the camera centre (not the origin, not the mean).
  Eigen::Matrix3d secondMoment() const {
    Eigen::Matrix3d s;
    s << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
    const Eigen::Vector3d q(sx, sy, sz);
    return s + origin * q.transpose() + q * origin.transpose() + n * origin * origin.transpose();
  }
};

// Least-squares plane of the moments: unit normal (eigenvector of the smallest eigenvalue of the
// scatter minus the expected noise scatter) and the eigenvalue divided by N, the mean squared
// point-to-plane distance (beyond the noise, when a noise scatter is given).
struct PlaneFitResult {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  double mse = 0.0;
};
PlaneFitResult fitPlane(const ScatterSums& sums,
                        const Eigen::Matrix3d& noise_scatter = Eigen::Matrix3d::Zero());

}  // namespace deepnav
