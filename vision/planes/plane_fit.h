#pragma once
#include <Eigen/Core>
#include <cstdint>

#include "vision/cloud/organized_cloud.h"
#include "vision/planes/plane.h"
#include "vision/planes/scatter_sums.h"

namespace deepnav {

// Stereo noise of one point, as seen by a plane: the error is along the viewing ray,
// sigma_Z = Z^2 sigma_d / (f B), sigma_ray = sigma_Z |p| / Z; projected on the normal n it is
// sigma_Z |n.p| / Z = Z sigma_d |d| / (f B) for a point on the plane n.p = d. An isotropic floor
// keeps planes seen edge-on (d -> 0) from claiming infinite precision.
struct PlaneNoiseModel {
  double disparity_noise_per_fb = 0.3 / 84.0;  // sigma_d / (f B), 1/m
  double floor_m = 0.002;
};

// Weighted least-squares plane of a grown region with its uncertainty (Pathak, Vaskevicius &
// Birk 2010; Pathak et al., IEEE T-RO 2010, the plane-parameter Hessian):
//   w_i = 1 / var_i (PlaneNoiseModel, with d from the unweighted fit),
//   M = sum w (p - m)(p - m)^T - sum w A_i, m = weighted mean, A_i = (k_d Z_i)^2 p_i p_i^T the
//   covariance of point i (disparity noise moves it along its ray),
//   n = smallest eigenvector of M (eigenvalue lambda), d = n . m,
//   H = [ M + W m m^T - lambda I, -W m ; -W m^T, W ] (4x4, rank 3, H (n, d) = 0), W = sum w.
// Subtracting the expected noise scatter sum w A_i removes the bias of total least squares under
// anisotropic noise: the rays of a stereo patch are nearly parallel, so raw TLS tilts the normal
// away from the viewing direction (3 deg for a 0.3 m patch at 2.2 m with 0.3 px noise).
// The covariance is the inverse of H on the tangent space of the constraint |n| = 1, i.e.
// C = B (B^T H B)^-1 B^T with B = [t1 t2 0; 0 0 1] (t1, t2 spanning n's orthogonal plane): the
// Laplace approximation on the manifold. (The plain pseudo-inverse H^+ projects along the null
// direction (n, d) instead, which moves part of the offset variance into a normal component along
// n when d != 0.) log_pdet_hessian is log |H|+, the product of H's three non-zero eigenvalues.
// `sums` are the region's unweighted moments (for the rms).
//
// Neighbouring planes: where two planes meet, which of them a cell joined depended on its noise
// (region growing and the boundary refinement hand ambiguous cells to the plane they fit better),
// so the cells kept near the intersection line are a noise-selected sample and tilt the normal
// (0.3-0.4 deg on a 0.7 m box face at 0.2 px noise). Cells whose noise-free position -- their ray
// cut with the region's plane, so the test does not depend on their own noise -- lies within
// band_m + band_sigmas * sigma of a neighbouring plane are therefore left out of the fit (not out
// of the region). Returns false for fewer than 3 fitted cells.
struct NeighbourBand {
  const Eigen::Vector4f* planes = nullptr;  // (n, d) of the neighbouring planes
  int count = 0;
  float band_m = 0.0f;
  float band_sigmas = 0.0f;
};
bool fitPlaneWithUncertainty(const OrganizedCloud& cloud, const std::int32_t* cells, int count,
                             const ScatterSums& sums, const Eigen::Vector3d& normal_unweighted,
                             const PlaneNoiseModel& noise, Plane* plane,
                             const NeighbourBand& neighbours = NeighbourBand{});

}  // namespace deepnav
