#pragma once
#include <cstdint>
#include <string>

#include <Eigen/Geometry>

#include "nav/ekf/ekf.h"
#include "nav/markers/marker_pose_covariance.h"
#include "nav/markers/panel_description.h"
#include "nav/markers/panel_pose_config.h"
#include "nav/markers/panel_pose_estimator.h"
#include "nav/pipeline/panel_anchor.h"
#include "nav/pipeline/pose_history.h"
#include "nav/types/vision_result.h"

namespace deepnav {

struct MarkerFusionCounters {
  std::uint32_t images = 0;              // vision results with at least one marker
  std::uint32_t observations = 0;        // marker observations seen
  std::uint32_t unknown_id = 0;          // not in the panel description
  std::uint32_t no_pose_at_capture = 0;  // capture time outside the pose history
  std::uint32_t fused = 0;               // pose measurements handed to the EKF (stage 2 of the chain)
  std::uint32_t accepted = 0;            // ... and accepted by its gate
};

// The markers' part of the method (paper, stage 1): while the panel is not fixed, every marker seen
// adds an estimate of the panel pose in odom, using the robot pose at the image's capture time; once the
// panel is fixed, every marker seen gives a robot pose (with a covariance growing with distance and
// obliqueness) fused by the EKF at the capture time.
class MarkerFusion {
 public:
  bool init(const PanelDescription& panel, const Eigen::Isometry3d& T_robot_cam, const PanelPoseConfig& pose_config,
            const MarkerCovarianceConfig& covariance_config, std::string* error);

  // One vision result; poses is the recent trajectory of the filter (for T_odom_robot at capture).
  // fuse_robot_pose false: once the panel is fixed the markers are seen and counted but not fused (the
  // paper's T_L3 test, stage 2 without markers).
  void onVision(const VisionResult& v, const PoseHistory& poses, Ekf* ekf, bool fuse_robot_pose = true);

  // Once the panel is fixed, fuse the markers against a clone of the robot pose at the fix instead of as
  // poses in odom (panel_anchor.h). Set after init(), before the first vision result.
  void holdPanelInFilter(bool on) { hold_panel_in_filter_ = on; }
  // The panel in odom: through the anchor clone when the filter holds the panel, else the fixed estimate.
  Eigen::Isometry3d panelInOdom(const Ekf& ekf) const;
  const PanelAnchor& anchor() const { return anchor_; }

  bool panelFixed() const { return estimator_.fixed(); }
  const PanelPoseEstimator& panelEstimator() const { return estimator_; }
  PanelPoseEstimator& panelEstimator() { return estimator_; }
  const MarkerFusionCounters& counters() const { return counters_; }
  // Fraction of the panel's faces on which a marker has been seen (stage machine criterion).
  double facesSeenFraction() const;

 private:
  void fuseMarker(TimeUs t_us, const MarkerObservation& obs, const PanelMarker& marker, Ekf* ekf);
  void fuseMarkerAgainstAnchor(TimeUs t_us, const MarkerObservation& obs, const PanelMarker& marker, Ekf* ekf);

  PanelDescription panel_;
  Eigen::Isometry3d T_robot_cam_ = Eigen::Isometry3d::Identity();
  MarkerCovarianceConfig covariance_config_;
  PanelPoseEstimator estimator_;
  MarkerFusionCounters counters_;
  std::uint32_t faces_seen_mask_ = 0;
  bool hold_panel_in_filter_ = false;
  PanelAnchor anchor_;
};

}  // namespace deepnav
