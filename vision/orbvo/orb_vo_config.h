#pragma once

#include "vision/orbvo/motion_prior.h"
#include "vision/orbvo/grid_orb_extractor.h"
#include "vision/orbvo/keyframe_policy.h"
#include "vision/orbvo/keyframe_relocaliser.h"
#include "vision/orbvo/local_bundle_adjuster.h"
#include "vision/orbvo/pnp_ransac.h"
#include "vision/orbvo/pose_refiner.h"
#include "vision/orbvo/projection_search.h"
#include "vision/orbvo/stereo_feature_matcher.h"

namespace deepnav {

// Every parameter of the ORB stereo odometry, with its unit and default. validate() says which is
// wrong.
struct OrbVoConfig {
  OrbExtractorConfig extractor;  // left image
  // Right image: cell budgets times this, so that the left corners are found again despite the
  // shift of the grid by the disparity, [1, 4]
  double right_budget_factor = 2.0;
  StereoMatchConfig stereo;
  PnpRansacConfig pnp;
  PoseRefinerConfig refiner;
  BundleAdjusterConfig bundle;
  KeyframePolicyConfig keyframe;

  double pixel_sigma_px = 1.0;  // corner noise at level 0 (level l: sigma * s^l), > 0

  // Tracking against the previous frame: its map points projected by the constant-velocity
  // prediction.
  ProjectionSearchConfig frame_search{15.0, 64, 0.9, 1};
  // Radius factor of the second attempt when matches are too few, >= 1
  double frame_search_widen = 3.0;
  int min_frame_matches = 30;  // fewer matches: second, wider attempt
  // Tracking against the local map: points of the local keyframes projected by the tracked pose.
  ProjectionSearchConfig map_search{5.0, 64, 0.9, 1};
  // Newest keyframes in the local map and the bundle adjustment, [2, max_keyframes)
  int local_keyframes = 5;
  // Fewer map points tracked: the frame is lost, >= min_inliers of the refiner
  int min_tracked = 20;

  int max_keyframes = 64;      // stored keyframes (local map + relocalisation), [3, 4096]
  int max_map_points = 20000;  // map point pool, >= 100
  int min_init_points = 50;    // stereo points needed to start a map

  RelocalisationConfig reloc;
  // Consecutive lost frames after which a new map starts; 0: never
  int reset_after_lost_frames = 0;
  // The navigation's predicted motion as the arbiter of the inliers (motion_prior.h); off by default.
  OrbMotionPriorConfig motion_prior;

  // Empty when valid, else the name of the first bad field and what it allows.
  const char* validate() const;
};

}  // namespace deepnav
