#include "vision/planes/scatter_sums.h"

#include <Eigen/Eigenvalues>

namespace deepnav {

PlaneFitResult fitPlane(const ScatterSums& sums, const Eigen::Matrix3d& noise_scatter) {
  PlaneFitResult fit;
  if (sums.n < 3.0) return fit;
  // computeDirect: closed-form 3x3 solver, no iterations, no allocation.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(sums.scatter() - noise_scatter);
  fit.normal = eig.eigenvectors().col(0);
  fit.mse = std::max(0.0, eig.eigenvalues()(0)) / sums.n;
  return fit;
}

}  // namespace deepnav
