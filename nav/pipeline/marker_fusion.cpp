#include "nav/pipeline/marker_fusion.h"

#include <bit>

#include "nav/markers/marker_pose_measurement.h"

namespace deepnav {

bool MarkerFusion::init(const PanelDescription& panel, const Eigen::Isometry3d& T_robot_cam,
                        const PanelPoseConfig& pose_config, const MarkerCovarianceConfig& covariance_config,
                        std::string* error) {
  if (panel.faces.size() > 32) {
    if (error) *error = "markers: at most 32 panel faces";
    return false;
  }
  if (!validateMarkerCovarianceConfig(covariance_config, error)) return false;
  panel_ = panel;
  T_robot_cam_ = T_robot_cam;
  covariance_config_ = covariance_config;
  counters_ = MarkerFusionCounters{};
  faces_seen_mask_ = 0;
  return estimator_.init(pose_config, error);
}

double MarkerFusion::facesSeenFraction() const {
  if (panel_.faces.empty()) return 0.0;
  return static_cast<double>(std::popcount(faces_seen_mask_)) / static_cast<double>(panel_.faces.size());
}

void MarkerFusion::fuseMarker(TimeUs t_us, const MarkerObservation& obs, const PanelMarker& marker, Ekf* ekf) {
  PoseMeasurement m;
  if (!markerPoseMeasurement(t_us, obs, marker, estimator_.estimate().inOdom(), T_robot_cam_, covariance_config_,
                             &m)) {
    return;
  }
  ++counters_.fused;
  if (ekf->fusePose(m).status == FuseStatus::kAccepted) ++counters_.accepted;
}

void MarkerFusion::onVision(const VisionResult& v, const PoseHistory& poses, Ekf* ekf, bool fuse_robot_pose) {
  if (!v.frame_ok || v.marker_count <= 0) return;
  ++counters_.images;
  Eigen::Isometry3d T_odom_robot;
  const bool have_pose = poses.poseAt(v.t_us, &T_odom_robot);
  for (int i = 0; i < v.marker_count && i < VisionResult::kMaxMarkers; ++i) {
    const MarkerObservation& obs = v.markers[static_cast<std::size_t>(i)];
    ++counters_.observations;
    const PanelMarker* marker = panel_.marker(obs.id);
    if (!marker) {
      ++counters_.unknown_id;
      continue;
    }
    faces_seen_mask_ |= 1u << static_cast<unsigned>(marker->face);
    if (estimator_.fixed()) {
      if (fuse_robot_pose) fuseMarker(v.t_us, obs, *marker, ekf);
    } else if (have_pose) {
      estimator_.addObservation(v.t_us, obs, *marker, T_odom_robot, T_robot_cam_);
    } else {
      ++counters_.no_pose_at_capture;
    }
  }
}

}  // namespace deepnav
