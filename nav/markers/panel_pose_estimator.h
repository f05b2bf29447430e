#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <bitset>
#include <cstdint>
#include <string>

#include "base/marker_observation.h"
#include "nav/markers/marker_pose_measurement.h"
#include "nav/markers/panel_description.h"
#include "nav/markers/panel_pose_config.h"
#include "nav/markers/panel_pose_record.h"
#include "nav/markers/quaternion_average.h"
#include "nav/types/time.h"

namespace deepnav {

// What became of one observation.
enum class PanelObservationVerdict : std::uint8_t {
  kAccepted = 0,
  kRejectedQuality,    // too far, too oblique or reprojection error too large
  kRejectedAmbiguous,  // ambiguous pose and no running mean to choose with (or use_ambiguous off)
  kRejectedOutlier,    // outside the gate around the running mean
  kRejectedInvalid,    // non-finite input, or a marker id >= 4096
  kIgnoredFixed,       // the panel is already fixed
};

struct PanelPoseCounters {
  std::uint32_t accepted = 0;
  std::uint32_t rejected_quality = 0;
  std::uint32_t rejected_ambiguous = 0;
  std::uint32_t rejected_outlier = 0;
  std::uint32_t rejected_invalid = 0;
  std::uint32_t ignored_fixed = 0;
  std::uint32_t unknown_markers = 0;  // ids not in the panel description (addFrame only)
  std::uint32_t ambiguous_resolved =
      0;                       // ambiguous poses accepted with the solution nearer the mean
  std::uint32_t restarts = 0;  // accumulations restarted after consecutive outliers
};

// The running (or fixed) panel pose in odom.
struct PanelPoseEstimate {
  Eigen::Vector3d p_panel_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_panel = Eigen::Quaterniond::Identity();
  Eigen::Matrix3d scatter_position_m2 =
      Eigen::Matrix3d::Zero();  // sample covariance of observations
  Eigen::Matrix3d scatter_rotation_rad2 =
      Eigen::Matrix3d::Zero();                                // the same for rotations, odom axes
  Eigen::Matrix3d cov_position_m2 = Eigen::Matrix3d::Zero();  // of the mean: scatter / n
  Eigen::Matrix3d cov_rotation_rad2 = Eigen::Matrix3d::Zero();
  std::int32_t observations = 0;
  std::int32_t distinct_markers = 0;
  bool fixed = false;
  TimeUs t_fixed_us = 0;

  Eigen::Isometry3d T_odom_panel() const;
  // Isotropic 1-sigma bounds (sqrt of the largest eigenvalue of cov_*), for
  // markerPoseMeasurement().
  PanelPoseInOdom inOdom() const;
};

// Stage 1 of the DexROV method: the panel's pose in odom from marker observations made while the
// filter navigates on its other sensors. Each observation gives
//   T_odom_panel = T_odom_robot * T_robot_cam * T_cam_marker * T_marker_panel
//   (marker_frame_chain.h)
// with T_odom_robot the filter's pose at the image time. Accepted observations are averaged:
// position by the arithmetic mean (Welford), orientation by the quaternion average of Markley et
// al. (quaternion_average.h); their scatter is the sample covariance. The panel becomes fixed when
// the thresholds of PanelPoseConfig hold, and stays fixed until reset(). No allocation.
class PanelPoseEstimator {
 public:
  bool init(const PanelPoseConfig& config, std::string* error);
  void reset();  // forget everything, including a fixed pose

  PanelObservationVerdict addObservation(TimeUs t_us, const MarkerObservation& obs,
                                         const PanelMarker& marker,
                                         const Eigen::Isometry3d& T_odom_robot,
                                         const Eigen::Isometry3d& T_robot_cam);
  // Every observation of one image whose id is in the panel; returns how many were accepted.
  int addFrame(TimeUs t_us, const MarkerObservations& observations, const PanelDescription& panel,
               const Eigen::Isometry3d& T_odom_robot, const Eigen::Isometry3d& T_robot_cam);

  bool fixed() const { return estimate_.fixed; }
  const PanelPoseEstimate& estimate() const { return estimate_; }
  const PanelPoseCounters& counters() const { return counters_; }
  const PanelPoseConfig& config() const { return config_; }

  // The fixed pose as plain numbers; false (and *out untouched) when not fixed.
  bool record(PanelPoseRecord* out) const;
  // Starts fixed at a saved pose. False with a message (and nothing changed) when the record is not
  // finite, its quaternion not unit or a covariance not symmetric positive semi-definite.
  bool restore(const PanelPoseRecord& record, std::string* error);

 private:
  static constexpr int kMaxMarkerId = 4096;

  bool passesQuality(const MarkerObservation& obs) const;
  bool insideGate(const Eigen::Isometry3d& T_odom_panel) const;
  void accumulate(TimeUs t_us, int marker_id, const Eigen::Isometry3d& T_odom_panel);
  void clearAccumulators();
  void updateEstimate();
  bool thresholdsMet() const;

  PanelPoseConfig config_;
  bool initialised_ = false;
  // Accumulators of the current (not yet fixed) average.
  int n_ = 0;
  Eigen::Vector3d mean_p_ = Eigen::Vector3d::Zero();
  Eigen::Matrix3d m2_p_ =
      Eigen::Matrix3d::Zero();  // Welford: sum of (p - mean)(p - mean_previous)^T
  QuaternionAverage rotations_;
  std::bitset<kMaxMarkerId> seen_ids_;
  int consecutive_outliers_ = 0;
  PanelPoseEstimate estimate_;
  PanelPoseCounters counters_;
};

}  // namespace deepnav
