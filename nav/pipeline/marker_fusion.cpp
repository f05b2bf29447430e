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
  anchor_.reset();
  return estimator_.init(pose_config, error);
}

double MarkerFusion::facesSeenFraction() const {
  if (panel_.faces.empty()) return 0.0;
  return static_cast<double>(std::popcount(faces_seen_mask_)) / static_cast<double>(panel_.faces.size());
}

Eigen::Isometry3d MarkerFusion::panelInOdom(const Ekf& ekf) const {
  if (hold_panel_in_filter_ && anchor_.counters().anchors > 0) return anchor_.T_odom_panel(ekf);
  return estimator_.estimate().T_odom_panel();
}

// The marker's robot pose relative to the anchor clone: markerPoseMeasurement() with the panel expressed
// in the anchor's frame gives T_anchor_robot and its covariance (isotropic blocks, so the same in the
// anchor frame and in the robot frame the relative measurement uses).
void MarkerFusion::fuseMarkerAgainstAnchor(TimeUs t_us, const MarkerObservation& obs, const PanelMarker& marker,
                                           Ekf* ekf) {
  if (!anchor_.ready(*ekf)) {
    if (!anchor_.anchored()) anchor_.anchor(t_us, panelInOdom(*ekf), ekf);
    if (!anchor_.ready(*ekf)) return;
  }
  PanelPoseInOdom in_anchor = estimator_.estimate().inOdom();
  in_anchor.T_odom_panel = anchor_.T_anchor_panel();
  PoseMeasurement pose;
  if (!markerPoseMeasurement(t_us, obs, marker, in_anchor, T_robot_cam_, covariance_config_, &pose)) return;
  RelativePoseMeasurement m;
  m.t_us = t_us;
  m.clone_id = anchor_.cloneId();
  m.q_robota_robotb = pose.q_odom_robot;
  m.p_robotb_in_robota_m = pose.p_robot_in_odom_m;
  m.cov = pose.cov_pose;
  m.source = kSrcMarkers;
  ++counters_.fused;
  if (ekf->fuseRelativePose(m).status == FuseStatus::kAccepted) ++counters_.accepted;
}

void MarkerFusion::fuseMarker(TimeUs t_us, const MarkerObservation& obs, const PanelMarker& marker, Ekf* ekf) {
  if (hold_panel_in_filter_) {
    fuseMarkerAgainstAnchor(t_us, obs, marker, ekf);
    return;
  }
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
