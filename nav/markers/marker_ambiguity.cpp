#include "nav/markers/marker_ambiguity.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace deepnav {

bool preferSolutionNear(const Eigen::Quaterniond& q_cam_marker_predicted, MarkerObservation* obs) {
  if (!obs->ambiguous) return false;
  const double best_rad = obs->q_cam_marker.angularDistance(q_cam_marker_predicted);
  const double alt_rad = obs->q_cam_marker_alt.angularDistance(q_cam_marker_predicted);
  if (!(alt_rad < best_rad)) return false;
  std::swap(obs->q_cam_marker, obs->q_cam_marker_alt);
  std::swap(obs->p_marker_in_cam_m, obs->p_marker_in_cam_alt_m);
  std::swap(obs->reprojection_error_px, obs->reprojection_error_alt_px);
  obs->distance_m = obs->p_marker_in_cam_m.norm();
  // Obliqueness of the new best pose: angle between its normal and the ray marker -> camera.
  const Eigen::Vector3d n = obs->q_cam_marker * Eigen::Vector3d::UnitZ();
  const double c = obs->distance_m > 0.0 ? -n.dot(obs->p_marker_in_cam_m) / obs->distance_m : 1.0;
  obs->obliqueness_rad = std::acos(std::clamp(c, -1.0, 1.0));
  return true;
}

}  // namespace deepnav
