#pragma once
#include <cstdint>
#include <vector>

#include "vision/orbvo/orb_frame.h"
#include "vision/orbvo/pnp_ransac.h"
#include "vision/orbvo/pose_refiner.h"
#include "vision/orbvo/stereo_rig.h"
#include "vision/orbvo/vo_map.h"

namespace deepnav {

// The camera pose of a frame from its feature-to-map-point associations: PnP RANSAC (optional),
// then the Huber Gauss-Newton refinement (refineCameraPose); the associations that end as
// outliers are dropped from the frame. Sized in init(); estimate() does not allocate.
class FramePoseEstimator {
 public:
  enum class Start {
    kGiven,          // refine from the given pose
    kRansacOrGiven,  // RANSAC first; from the given pose if it fails
    kRansacOnly,     // RANSAC must succeed (no prior pose to fall back on)
  };

  // level_sigma_px[l]: 1-sigma pixel noise of a corner of pyramid level l.
  bool init(const StereoRig& rig, const PnpRansacConfig& pnp, const PoseRefinerConfig& refiner,
            const std::vector<double>& level_sigma_px, int capacity);

  // *pose: the start (kGiven, or the fallback of kRansacOrGiven) in, the estimate out. On success
  // frame->tracked is the number of inliers.
  bool estimate(Start start, const VoMap& map, OrbFrame* frame, CameraPoseEstimate* pose);

 private:
  StereoRig rig_{};
  PnpRansacConfig pnp_config_{};
  PoseRefinerConfig refiner_{};
  std::vector<double> level_sigma_px_;
  PnpRansac pnp_;
  std::vector<PoseObservation> observations_;
  std::vector<int> observation_feature_;  // per observation, its feature in the frame
  std::vector<std::uint8_t> inlier_;
};

}  // namespace deepnav
