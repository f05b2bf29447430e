#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

#include "nav/types/time.h"

namespace deepnav {

enum class OrbVoStatus : std::uint8_t {
  kInitialised = 0,  // a map started on this frame: no relative pose
  kOk = 1,           // tracked: relative pose to the previous frame
  kLost = 2,         // not tracked: no relative pose
  // Found again against a stored keyframe: relative pose to the last tracked frame
  kRelocalised = 3,
};

const char* toString(OrbVoStatus status);

// Result of one stereo pair. The relative pose is that of the left camera (optical frame C) at this
// frame (b) in the left camera at the reference frame (a); the caller turns it into a
// RelativePoseMeasurement of the robot with the camera mounting.
struct OrbVoOutput {
  TimeUs t_us = 0;            // capture time of this pair (b)
  TimeUs t_reference_us = 0;  // capture time of frame a: the previous pair, or the last tracked one
  OrbVoStatus status = OrbVoStatus::kLost;
  bool hasRelativePose() const {
    return status == OrbVoStatus::kOk || status == OrbVoStatus::kRelocalised;
  }

  Eigen::Quaterniond q_cama_camb = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_camb_in_cama_m = Eigen::Vector3d::Zero();
  // [x y z roll pitch yaw]: translation error in frame a, rotation error about the axes of b with
  // q_meas = q_true Exp(n) -- the convention of RelativePoseMeasurement::cov.
  Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Identity();

  // Map points tracked in this frame (inliers of the final pose): the m_I of the paper
  int tracked_features = 0;
  int left_features = 0;             // ORB features of the left image
  int stereo_points = 0;             // left features with a stereo match
  double reprojection_rms_px = 0.0;  // RMS of the final pose's inlier residuals
  bool keyframe_inserted = false;
  bool prior_reselected = false;  // inliers re-selected around the navigation's predicted motion
  int keyframes = 0;   // stored
  int map_points = 0;  // alive

  // Pose of the left camera in the odometry world W (the first keyframe's camera frame),
  // diagnostics.
  Eigen::Quaterniond q_world_cam = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_cam_in_world_m = Eigen::Vector3d::Zero();
};

}  // namespace deepnav
