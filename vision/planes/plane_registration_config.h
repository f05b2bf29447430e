#pragma once

namespace deepnav {

// Plane registration after Pathak, Birk, Vaskevicius & Poppinga, "Fast registration based on
// noisy planes with unknown correspondences for 3-D mapping", IEEE T-RO 2010.
struct PlaneRegistrationConfig {
  // Unary tests on a candidate pair (plane i of image a, plane j of image b):
  // size similarity |log|H_i|+ - log|H_j|+| (|.|+ pseudo-determinant of the plane Hessian,
  // which grows with the point count and the plane's extent): 3.0 admits ~2.7x the points.
  double max_log_size_ratio = 3.0;
  // Prior on the rotation between the two images: angle between n_i and n_j compared directly
  // (deg, 180 disables), and the bound on the fitted rotation (a larger one is rejected as a wrong
  // correspondence). Vision runs at a few Hz; 45 deg is far beyond an ROV's turn rate.
  double max_normal_change_deg = 45.0;
  // Binary tests on two candidate pairs (i, j), (k, l):
  double max_cross_angle_diff_deg = 4.0;     // |angle(n_i, n_k) - angle(n_j, n_l)|
  double parallel_angle_deg = 8.0;           // planes closer than this are "parallel"
  double max_parallel_offset_diff_m = 0.10;  // parallel: |(d_i - d_k) - (d_j - d_l)|
  // Verification of the chosen correspondence set after the fit:
  double max_residual_angle_deg = 3.0;  // angle(n_i, R n_j)
  double max_offset_residual_m = 0.10;  // |n_i . t - (d_i - d_j)|
  // Translation needs normals spanning 3D: smallest eigenvalue of mean(n n^T) (1/3 for three
  // orthogonal planes, 0.02 ~ the third normal 14 deg out of the others' plane).
  double min_translation_eigenvalue = 0.02;
  // Variance (rad^2, m^2) written for directions the planes do not constrain.
  double unobservable_variance = 1e4;
  // Multiplies the output covariance: the per-point stereo errors are correlated (window
  // matching, interpolation), so the independent-noise covariance is optimistic.
  double covariance_scale = 1.0;
  // Degenerate sets contribute the directions they constrain (false: the paper's behaviour, a result
  // needs two non-parallel planes and its translation three spanning 3D). When true, parallel planes
  // only (one plane, or a face and its fixtures) give the two rotation axes across their normal (the
  // smallest rotation taking the normals of b onto those of a, nothing about the normal) and every
  // result the translation in the span of its normals (one plane: along it; two: their span).
  bool subspace = false;
  // Budget of the consistent-set search (branch-and-bound nodes); 0 = unlimited.
  int max_search_nodes = 50000;
};

}  // namespace deepnav
