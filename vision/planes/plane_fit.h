#pragma once
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <opencv2/core/hal/intrin.hpp>

#include "vision/cloud/organized_cloud.h"
#include "vision/planes/plane.h"
#include "vision/planes/scatter_sums.h"
#include "vision/planes/tile_sums.h"

namespace deepnav {

// Stereo noise of one point, as seen by a plane: the error is along the viewing ray,
// sigma_Z = Z^2 sigma_d / (f B), sigma_ray = sigma_Z |p| / Z; projected on the normal n it is
// sigma_Z |n.p| / Z = Z sigma_d |d| / (f B) for a point on the plane n.p = d. An isotropic floor
// keeps planes seen edge-on (d -> 0) from claiming infinite precision.
//
// Correlated errors: dense stereo does not measure every pixel independently. Windows overlap, and on
// weakly textured surfaces (murky water, a plain panel face) ELAS matches a few support points and
// interpolates the disparity between them, so the depth error of a whole face is set by a handful of
// matches. The fit's covariance, which assumes independent cells, then shrinks as 1/N while the error
// does not (measured on the sea-trial dive: plane registrations 30-100x their predicted sigma).
// independent_points > 0 caps the cells counted as independent: the covariance is that of a fit of
// independent_points cells spread as the fitted ones, C * N_fit / independent_points (N_fit above it).
struct PlaneNoiseModel {
  double disparity_noise_per_fb = 0.3 / 84.0;  // sigma_d / (f B), 1/m
  double floor_m = 0.002;
  double independent_points = 0.0;  // 0: every fitted cell independent
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
// of the region). At most 16 neighbouring planes are used. Returns false for fewer than 3 fitted
// cells.
struct NeighbourBand {
  const Eigen::Vector4f* planes = nullptr;  // (n, d) of the neighbouring planes
  int count = 0;
  float band_m = 0.0f;
  float band_sigmas = 0.0f;
};

// Weighted first and second moments, in plain doubles.
struct WeightedMoments {
  double w = 0.0, x = 0.0, y = 0.0, z = 0.0;
  double xx = 0.0, xy = 0.0, xz = 0.0, yy = 0.0, yz = 0.0, zz = 0.0;
  void add(double px, double py, double pz, double weight) {
    w += weight;
    const double wx = weight * px, wy = weight * py, wz = weight * pz;
    x += wx;
    y += wy;
    z += wz;
    xx += wx * px;
    xy += wx * py;
    xz += wx * pz;
    yy += wy * py;
    yz += wy * pz;
    zz += wz * pz;
  }
  void merge(const WeightedMoments& o) {
    w += o.w;
    x += o.x;
    y += o.y;
    z += o.z;
    xx += o.xx;
    xy += o.xy;
    xz += o.xz;
    yy += o.yy;
    yz += o.yz;
    zz += o.zz;
  }
  Eigen::Vector3d first() const { return Eigen::Vector3d(x, y, z); }
  Eigen::Matrix3d second() const {
    Eigen::Matrix3d m;
    m << xx, xy, xz, xy, yy, yz, xz, yz, zz;
    return m;
  }
};

// The fit below, cell by cell in any order (the extractor feeds all planes in one raster pass,
// which reads the cloud sequentially instead of in region-growing order), then solved.
class PlaneFitAccumulator {
 public:
  void reset(const ScatterSums& sums, const Eigen::Vector3d& normal_unweighted,
             const PlaneNoiseModel& noise, const NeighbourBand& neighbours);
  void add(const cv::Vec3f& p) { addRun(&p, 1); }
  // count consecutive cells of this plane (a run of a row): the neighbour-band test and the
  // weights four cells at a time (SIMD, the same float operations as the scalar path), the
  // moments summed in registers in cell order, then merged (plane_fit.cpp).
  void addRun(const cv::Vec3f* p, int count);
  // The cells of one tile whose label is `label` (labels: the tile's first label, row stride
  // label_stride), for the tile grower: the same neighbour-band test, but the moments summed in
  // float four lanes at a time relative to the tile's ref, then moved to the origin in double,
  // and one weight per tile (at the mean Z^2 of its fitted cells) instead of one per cell.
  // Returns the bounding box of the tile's cells with that label (empty when none).
  // lo, hi: the box of the tile's points; neighbours whose band cannot reach it are not tested.
  cv::Rect addTile(const TileView& tile, const cv::Vec3f& ref, const cv::Vec3f& lo,
                   const cv::Vec3f& hi, const std::uint8_t* labels, int label_stride,
                   std::uint8_t label);
  // A tile all of whose valid cells are this plane's, from its moments `sums` (relative to ref),
  // without reading its cells; false (nothing added) when a neighbour's band may reach the box
  // [lo, hi] of its points: then addTile must test its cells.
  bool addWholeTile(const TileSums& sums, const cv::Vec3f& ref, const cv::Vec3f& lo,
                    const cv::Vec3f& hi);
  // sums: the region's unweighted moments (rms); point_count: the region's cells.
  bool solve(const ScatterSums& sums, int point_count, Plane* plane) const;

 private:
  bool inNeighbourBand(const cv::Vec3f& p) const;
  // Four cells from p: bit i set when cell i is in a neighbour's band (inNeighbourBand);
  // *w receives their weights 1 / ((k Z)^2 + floor^2).
  unsigned bandMask4(const cv::Vec3f* p, float* w) const;
  // Fitted cells' moments relative to ref, with one weight for the tile (addTile).
  void addTileMoments(const TileSums& t, const cv::Vec3f& ref);
  // bandMask4's in-band mask on loaded lanes, without the weights (addTile).
  // Only the neighbours active[0..count) are tested.
  cv::v_float32x4 bandLanes(const cv::v_float32x4& x, const cv::v_float32x4& y,
                            const cv::v_float32x4& z, const int* active, int count) const;
  // The neighbours whose band may hold a point of the box [lo, hi] (interval bounds of the
  // inNeighbourBand test over the box); returns their number.
  int neighboursNear(const cv::Vec3f& lo, const cv::Vec3f& hi, int* active) const;
  void addCell(const cv::Vec3f& p, double w, WeightedMoments* sw, WeightedMoments* sa) const {
    const double x = p[0] - origin_.x(), y = p[1] - origin_.y(), z = p[2] - origin_.z();
    sw->add(x, y, z, w);
    sa->add(x, y, z, w * kd2_ * p[2] * p[2]);
  }

  static constexpr int kMaxNeighbours = 16;
  Eigen::Vector3d origin_ = Eigen::Vector3d::Zero();
  Eigen::Vector3f n0_ = Eigen::Vector3f::UnitZ();
  float d0_ = 0.0f;   // signed offset of the unweighted plane
  float kd_ = 0.0f;   // sigma_d / (f B)
  double k_ = 0.0;    // residual sigma = k Z
  double kd2_ = 0.0;  // kd^2
  double floor2_ = 0.0;
  double independent_points_ = 0.0;
  float kf_ = 0.0f;
  float floor2f_ = 0.0f;
  // Per neighbouring plane j, for the division-free band test: d0 n_j, d_j, and
  // band_sigmas kd |d_j| |d0| (see inNeighbourBand).
  int neighbour_count_ = 0;
  float band_m_ = 0.0f;
  std::array<Eigen::Vector3f, kMaxNeighbours> d0_n_{};
  std::array<float, kMaxNeighbours> d_{};
  std::array<float, kMaxNeighbours> sigma_coeff_{};
  // The same constants repeated in four lanes for bandMask4 (a broadcast per use costs more than
  // the test): kf, floor^2, n0 x y z, band_m; per neighbour d0 n_j x y z, d_j, sigma coefficient.
  std::array<std::array<float, 4>, 6> lanes_{};
  std::array<std::array<std::array<float, 4>, 5>, kMaxNeighbours> neighbour_lanes_{};
  WeightedMoments sw_, sa_;  // weights w_i and a_i = w_i (k_d Z_i)^2
  int fitted_ = 0;
};

bool fitPlaneWithUncertainty(const OrganizedCloud& cloud, const std::int32_t* cells, int count,
                             const ScatterSums& sums, const Eigen::Vector3d& normal_unweighted,
                             const PlaneNoiseModel& noise, Plane* plane,
                             const NeighbourBand& neighbours = NeighbourBand{});

}  // namespace deepnav
