#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

#include "base/marker_observation.h"
#include "vision/markers/pinhole_intrinsics.h"

namespace deepnav {

// When both IPPE solutions are flagged ambiguous. Under Gaussian corner noise of sigma per axis,
// the sum of squared corner residuals of a pose is SSR = 4 e^2 (e: RMS corner distance over the 4
// corners). The alternative solution is rejected as implausible only when it explains the corners
// clearly worse:
//   ambiguous  <=>  4 (e_alt^2 - e_best^2) / sigma^2 < ambiguity_chi2
// (a likelihood-ratio test; chi2 = 9 is "3 sigma" for one degree of freedom).
struct MarkerAmbiguityConfig {
  double corner_sigma_px = 0.3;  // 1-sigma corner noise per axis after subpixel refinement, px, > 0
  double ambiguity_chi2 = 9.0;   // threshold of the test above, >= 0 (0: never ambiguous)
};

// Pose of a square marker of side marker_size_m from its 4 corners (ArUco order, see
// MarkerObservation) by cv::solvePnPGeneric(SOLVEPNP_IPPE_SQUARE) (Collins & Bartoli,
// "Infinitesimal Plane-based Pose Estimation", IJCV 2014), which returns both solutions of the
// planar ambiguity. Fills every pose field of *out (the best solution, the other, their
// reprojection errors, the ambiguity flag, distance and obliqueness); id and corners are left to
// the caller. False (and *out untouched) when no finite solution with the marker in front of the
// camera exists.
bool estimateSquareMarkerPose(const std::array<Eigen::Vector2d, 4>& corners_px,
                              double marker_size_m, const PinholeIntrinsics& camera,
                              const MarkerAmbiguityConfig& ambiguity, MarkerObservation* out);

// Corner k of a square marker of side L in its own frame M: (-L/2, L/2, 0), (L/2, L/2, 0),
// (L/2, -L/2, 0), (-L/2, -L/2, 0) -- ArUco's order, the one SOLVEPNP_IPPE_SQUARE requires.
Eigen::Vector3d squareMarkerCorner(int k, double marker_size_m);

// RMS over the 4 corners of |projection of T_cam_marker * corner_k - corners_px[k]|, px.
// +infinity when a corner projects behind the camera.
double markerReprojectionErrorPx(const std::array<Eigen::Vector2d, 4>& corners_px,
                                 double marker_size_m, const PinholeIntrinsics& camera,
                                 const Eigen::Quaterniond& q_cam_marker,
                                 const Eigen::Vector3d& p_marker_in_cam_m);

// Angle between the marker's normal (z of M) and the ray from the marker to the camera, in [0, pi]:
// 0 when the camera looks straight at the marker, pi/2 when it sees the marker edge-on.
double markerObliquenessRad(const Eigen::Quaterniond& q_cam_marker,
                            const Eigen::Vector3d& p_marker_in_cam_m);

}  // namespace deepnav
