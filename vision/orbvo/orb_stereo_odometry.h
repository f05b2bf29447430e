#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "vision/orbvo/frame_pose_estimator.h"
#include "vision/orbvo/grid_orb_extractor.h"
#include "vision/orbvo/keyframe_relocaliser.h"
#include "vision/orbvo/local_window_adjustment.h"
#include "vision/orbvo/map_point_search.h"
#include "vision/orbvo/orb_frame.h"
#include "vision/orbvo/orb_vo_config.h"
#include "vision/orbvo/orb_vo_output.h"
#include "vision/orbvo/stereo_feature_matcher.h"
#include "vision/orbvo/stereo_rig.h"
#include "vision/orbvo/vo_map.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

// ORB stereo visual odometry with a local map: the DexROV paper's ORB odometry (IROS 2019), with
// the tracking / local-map / keyframe structure of ORB-SLAM2 (Mur-Artal & Tardos, T-RO 2017),
// written from the papers. Per stereo pair:
//  1. bucketed ORB on both images (GridOrbExtractor), row-band stereo matching with subpixel
//     disparity and triangulation (StereoFeatureMatcher);
//  2. tracking: the previous frame's map points projected by a constant-velocity prediction and
//     matched in a window; pose by PnP RANSAC then Huber Gauss-Newton on the stereo reprojection
//     error (refineCameraPose); then the points of the local keyframes projected by that pose,
//     matched in a small window; tracked corners the stereo matcher missed get their right column
//     from a ZSAD search around the disparity their map point predicts; a second refinement, whose
//     inliers are the tracked features;
//  3. keyframe policy; a keyframe adds the untracked stereo points to the map and runs a windowed
//     bundle adjustment of the newest keyframes, the oldest fixed (LocalBundleAdjuster);
//  4. when tracking fails: relocalisation against the stored keyframes (thumbnail similarity, then
//     descriptor matches of the most similar, then PnP RANSAC and refinement on the best).
// Output: relative pose of this frame's left camera in the previous (or last tracked) frame's, its
// 6x6 covariance, the number of tracked features and a status.
//
// Pure: no threads, files or clocks. Allocation: every buffer of our own is sized in init(); in the
// steady state the remaining allocations are OpenCV's (cv::solvePnPRansac, cv::resize on some builds;
// cv::FAST only where FastCornerMap cannot reproduce it), documented in the README of this folder.
class OrbStereoOdometry {
 public:
  // False with *error naming the bad field or size.
  bool init(const OrbVoConfig& config, const StereoRig& rig, std::string* error);

  // Forgets the map: the next frame starts a new one.
  void reset();

  // One rectified stereo pair of the rig's size, CV_8UC1 or CV_8UC3. Returns false (status kLost)
  // for a frame that cannot be used (wrong size or type, not rectified).
  bool process(TimeUs t_us, const cv::Mat& left, const cv::Mat& right, OrbVoOutput* out);
  bool process(const StereoFrame& frame, OrbVoOutput* out);

  // The navigation's pose of the left camera at the next pair's capture (any fixed frame): with
  // config.motion_prior.enabled, the motion it predicts since the last tracked pair arbitrates the
  // inliers when the VO disagrees with it (motion_prior.h). Applies to the next process() only.
  void setMotionPrior(const Eigen::Isometry3d& T_odom_cam) {
    prior_next_ = true;
    prior_next_T_odom_cam_ = T_odom_cam;
  }

 private:
  struct TrackedPose {
    TimeUs t_us = 0;
    CameraPoseEstimate pose;
    bool has_prior = false;  // the navigation's pose of this pair
    Eigen::Isometry3d T_odom_cam_prior = Eigen::Isometry3d::Identity();
  };

  bool detect(TimeUs t_us, const cv::Mat& left, const cv::Mat& right);
  bool startMap(OrbVoOutput* out);
  void rememberTracked();
  bool trackFrame();
  bool relocalise();
  bool reselectWithPrior();
  int completeStereo(const CameraPoseEstimate& pose);
  bool estimatePose(FramePoseEstimator::Start start, CameraPoseEstimate* pose) {
    return pose_estimator_.estimate(start, map_, &cur_, pose);
  }
  bool keyframeNeeded() const;
  void insertKeyframe();
  void fillOutput(OrbVoOutput* out) const;

  bool ready_ = false;
  OrbVoConfig config_{};
  StereoRig rig_{};
  GridOrbExtractor extractor_;        // left image
  GridOrbExtractor right_extractor_;  // right image (its own FAST thresholds and a larger budget)
  StereoFeatureMatcher stereo_;
  MapPointSearch search_;
  FramePoseEstimator pose_estimator_;
  LocalWindowAdjustment window_adjustment_;
  KeyframeRelocaliser relocaliser_;
  VoMap map_;

  cv::Mat grey_left_, grey_right_;  // BGR input converted
  cv::Mat cur_left_, cur_right_;    // headers of this frame's grey images
  std::vector<OrbFeature> right_features_;
  std::vector<OrbDescriptor> right_descriptors_;
  OrbFrame cur_, prev_;
  std::vector<double> level_sigma_px_;  // per pyramid level, the corner noise

  // Tracking state.
  bool initialised_ = false;
  bool lost_ = false;
  int lost_frames_ = 0;
  int frames_since_keyframe_ = 0;
  bool keyframe_inserted_ = false;
  bool has_velocity_ = false;
  Eigen::Matrix3d R_velocity_ = Eigen::Matrix3d::Identity();  // T_cur_prev of the last step
  Eigen::Vector3d t_velocity_ = Eigen::Vector3d::Zero();
  TrackedPose last_tracked_;
  bool prior_next_ = false;  // setMotionPrior() for the next pair
  Eigen::Isometry3d prior_next_T_odom_cam_ = Eigen::Isometry3d::Identity();
  bool prior_cur_ = false;   // this pair's
  Eigen::Isometry3d prior_cur_T_odom_cam_ = Eigen::Isometry3d::Identity();
  bool prior_reselected_ = false;
  std::vector<int> saved_map_point_;  // associations before a re-selection (restored if it fails)
  std::vector<int> saved_match_distance_;
};

}  // namespace deepnav
