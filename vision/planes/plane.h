#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>

namespace deepnav {

// One plane extracted from an organised cloud, in the camera optical frame C of that cloud.
// Hessian normal form: n . p = d for every point p on the plane. The normal points to the camera
// (n . centroid < 0), hence d = -(distance of the plane from the camera centre) < 0.
struct Plane {
  Eigen::Vector3d n_in_cam = Eigen::Vector3d::UnitZ();
  double d_m = 0.0;
  Eigen::Vector3d p_centroid_in_cam_m = Eigen::Vector3d::Zero();  // weighted mean of the points
  int point_count = 0;                                            // cells of the region
  int fit_point_count = 0;  // cells in the fit (those away from intersections, plane_fit.h)
  double rms_m = 0.0;       // root mean square point-to-plane distance (unweighted)

  // Uncertainty of theta = (n, d) after Pathak et al. 2010: `hessian` is the Hessian of the
  // weighted least-squares cost 1/2 sum w_i (n.p_i - d)^2 with the |n| = 1 Lagrange term,
  //   H = [ sum w p p^T - lambda I   -sum w p ]
  //       [ -sum w p^T                sum w   ],   lambda = smallest eigenvalue of the scatter,
  // rank 3, null direction (n, d); `covariance` = H^+ (m^2-free: n unitless, d in m).
  // log_pdet_hessian = log |H|+ (product of the three non-zero eigenvalues), the "size" of the
  // plane in the registration's size-similarity test.
  Eigen::Matrix4d hessian = Eigen::Matrix4d::Zero();
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Zero();
  double log_pdet_hessian = 0.0;

  std::uint8_t label = 0;  // value of this plane in the extractor's label grid (1-based)
  cv::Rect bbox_cells;     // bounding box in grid cells of the cloud
  int polygon_begin = 0;   // into PlaneSet::polygon(): the outer boundary, then the holes
  int polygon_count = 0;

  Eigen::Matrix3d normalCovariance() const { return covariance.topLeftCorner<3, 3>(); }
  double offsetVariance() const { return covariance(3, 3); }
};

// A closed polygon of a plane: the chain of boundary cells (8-connected border following,
// straight runs compressed to their end points), vertices in image pixels (cell * step_px).
// The outer boundary runs around the plane's cells; a hole's polygon runs through the plane's
// cells that surround the hole.
struct PlanePolygon {
  int plane = -1;  // index into the PlaneSet
  bool is_hole = false;
  int point_begin = 0;  // into PlaneSet::polygonPoint()
  int point_count = 0;
  double area_px2 = 0.0;  // |shoelace area| of the vertex chain, image pixels^2
};

}  // namespace deepnav
