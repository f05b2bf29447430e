#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "vision/orbvo/local_bundle_adjuster.h"
#include "vision/orbvo/orb_frame.h"
#include "vision/orbvo/stereo_rig.h"
#include "vision/orbvo/vo_map.h"

namespace deepnav {

// The bundle adjustment run after each keyframe: the newest `window` keyframes of the map and the
// points they see, the oldest keyframe of the window fixed (it holds the gauge). Gathers the
// problem from the map, solves it (LocalBundleAdjuster) and writes back the poses, the points and
// the outlier observations (their references released). Sized in init(); does not allocate after.
class LocalWindowAdjustment {
 public:
  // level_sigma_px[l]: 1-sigma pixel noise of a corner of pyramid level l; capacity: features per
  // keyframe.
  bool init(const StereoRig& rig, const BundleAdjusterConfig& config, int window,
            const std::vector<double>& level_sigma_px, int capacity);

  // Adjusts the window ending at the newest keyframe, which is `newest` (the current frame): its
  // pose and map points follow the adjustment.
  void adjust(VoMap* map, OrbFrame* newest);

 private:
  // Fills the cameras, points and observations; returns the window size.
  int gather(VoMap* map, int* n_points, int* n_observations);
  void writeBack(int window, int n_points, int n_observations, VoMap* map, OrbFrame* newest) const;

  StereoRig rig_{};
  BundleAdjusterConfig config_{};
  int window_ = 0;
  std::vector<double> level_sigma_px_;
  LocalBundleAdjuster bundle_adjuster_;
  std::vector<Eigen::Matrix3d> R_cam_world_;         // per window camera, 0 the oldest keyframe
  std::vector<Eigen::Vector3d> p_world_in_cam_m_;
  std::vector<Eigen::Vector3d> p_in_world_m_;        // per point
  std::vector<int> point_id_;                        // per point, its map point
  std::vector<BaObservation> observations_;
  std::vector<int> source_age_;                      // per observation, its keyframe's age
  std::vector<int> source_feature_;                  // per observation, its keyframe feature
  std::vector<std::uint8_t> outlier_;
};

}  // namespace deepnav
