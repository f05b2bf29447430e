#include "vision/orbvo/frame_pose_estimator.h"

#include <limits>

namespace deepnav {

bool FramePoseEstimator::init(const StereoRig& rig, const PnpRansacConfig& pnp,
                              const PoseRefinerConfig& refiner,
                              const std::vector<double>& level_sigma_px, int capacity) {
  rig_ = rig;
  pnp_config_ = pnp;
  refiner_ = refiner;
  level_sigma_px_ = level_sigma_px;
  if (!pnp_.init(capacity)) return false;
  observations_.reserve(capacity);
  observation_feature_.reserve(capacity);
  inlier_.assign(capacity, 0);
  return true;
}

bool FramePoseEstimator::estimate(Start start, const VoMap& map, OrbFrame* frame,
                                  CameraPoseEstimate* pose) {
  observations_.clear();
  observation_feature_.clear();
  for (std::size_t j = 0; j < frame->map_point.size(); ++j) {
    const int m = frame->map_point[j];
    if (m < 0) continue;
    const OrbFeature& f = frame->features[j];
    PoseObservation o;
    o.p_in_world_m = map.point(m).p_in_world_m;
    o.uv_px = {f.u_px, f.v_px};
    o.u_right_px = frame->u_right_px[j];
    o.sigma_px = level_sigma_px_[f.level];
    observations_.push_back(o);
    observation_feature_.push_back(static_cast<int>(j));
  }
  int n = static_cast<int>(observations_.size());
  if (n < refiner_.min_inliers) return false;
  CameraPoseEstimate estimate = *pose;
  if (start != Start::kGiven) {
    pnp_.clear();
    for (const PoseObservation& o : observations_) pnp_.add(o.p_in_world_m, o.uv_px);
    if (pnp_.solve(rig_, pnp_config_, &estimate, inlier_.data())) {
      // Keep the RANSAC inliers only.
      int kept = 0;
      for (int k = 0; k < n; ++k) {
        if (inlier_[k]) {
          observations_[kept] = observations_[k];
          observation_feature_[kept] = observation_feature_[k];
          ++kept;
        } else {
          frame->map_point[observation_feature_[k]] = -1;
        }
      }
      n = kept;
    } else if (start == Start::kRansacOnly) {
      return false;
    }  // else RANSAC failed: start from the given pose, the Huber loss and the gates must cope
  }
  if (!refineCameraPose(rig_, refiner_, observations_.data(), n, inlier_.data(), &estimate))
    return false;
  for (int k = 0; k < n; ++k) {
    const int j = observation_feature_[k];
    if (!inlier_[k]) frame->map_point[j] = -1;
  }
  for (std::size_t j = 0; j < frame->map_point.size(); ++j) {
    if (frame->map_point[j] < 0) frame->match_distance[j] = std::numeric_limits<int>::max();
  }
  *pose = estimate;
  frame->tracked = estimate.inliers;
  return true;
}

}  // namespace deepnav
