#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>

namespace deepnav {

// One square fiducial marker seen in one rectified image, with its pose in the camera optical frame
// C (z forward, x right, y down). Marker frame M as in nav/markers/panel_description.h (OpenCV
// ArUco): origin at the marker centre, x right, y up, z out of the face towards the camera. Plain
// data, no OpenCV type: the detector (vision/markers) writes it, VisionResult (nav/types) carries it.
struct MarkerObservation {
  std::int32_t id = -1;
  // Corners in pixels (pixel centres at integer coordinates, OpenCV convention), in the ArUco
  // order: top-left, top-right, bottom-right, bottom-left of the marker as printed, i.e. the points
  // (-L/2, L/2, 0), (L/2, L/2, 0), (L/2, -L/2, 0), (-L/2, -L/2, 0) of M.
  std::array<Eigen::Vector2d, 4> corners_px{Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                                            Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
  // Best pose (lower reprojection error of the two IPPE solutions): T_cam_marker.
  Eigen::Quaterniond q_cam_marker = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_marker_in_cam_m = Eigen::Vector3d::Zero();
  // The other IPPE solution (planar pose ambiguity: the marker tilted the other way), kept so that
  // a consumer with prior knowledge (e.g. the panel pose) can pick it instead.
  Eigen::Quaterniond q_cam_marker_alt = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_marker_in_cam_alt_m = Eigen::Vector3d::Zero();
  double reprojection_error_px = 0.0;      // RMS corner distance of the best pose
  double reprojection_error_alt_px = 0.0;  // the same for the other solution (>= the best)
  bool ambiguous = false;                  // both solutions explain the corners about as well
  double distance_m = 0.0;                 // |p_marker_in_cam_m|
  double obliqueness_rad = 0.0;  // angle between the marker normal and the ray marker->camera
};

// Every marker of one image, in a fixed-capacity array (no allocation).
struct MarkerObservations {
  static constexpr int kCapacity = 32;
  std::array<MarkerObservation, kCapacity> items{};
  std::int32_t count = 0;          // valid entries: items[0 .. count)
  std::int32_t dropped = 0;        // detections beyond kCapacity, not reported
  std::int32_t pose_failures = 0;  // detections whose pose could not be computed, not reported

  void clear() { count = dropped = pose_failures = 0; }
};

}  // namespace deepnav
