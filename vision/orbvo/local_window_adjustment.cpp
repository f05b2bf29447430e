#include "vision/orbvo/local_window_adjustment.h"

#include <algorithm>

namespace deepnav {

bool LocalWindowAdjustment::init(const StereoRig& rig, const BundleAdjusterConfig& config,
                                 int window, const std::vector<double>& level_sigma_px,
                                 int capacity) {
  rig_ = rig;
  config_ = config;
  window_ = window;
  level_sigma_px_ = level_sigma_px;
  if (!bundle_adjuster_.init(window, window * capacity, window * capacity)) return false;
  R_cam_world_.assign(window, Eigen::Matrix3d::Identity());
  p_world_in_cam_m_.assign(window, Eigen::Vector3d::Zero());
  p_in_world_m_.assign(window * capacity, Eigen::Vector3d::Zero());
  point_id_.assign(window * capacity, -1);
  observations_.assign(window * capacity, BaObservation());
  source_age_.assign(window * capacity, 0);
  source_feature_.assign(window * capacity, 0);
  outlier_.assign(window * capacity, 0);
  return true;
}

void LocalWindowAdjustment::adjust(VoMap* map, OrbFrame* newest) {
  int n_points = 0;
  int n_obs = 0;
  const int window = gather(map, &n_points, &n_obs);
  BundleAdjusterSummary summary;
  if (!bundle_adjuster_.optimise(rig_, config_, window, 1, R_cam_world_.data(),
                                 p_world_in_cam_m_.data(), n_points, p_in_world_m_.data(), n_obs,
                                 observations_.data(), outlier_.data(), &summary)) {
    return;
  }
  writeBack(window, n_points, n_obs, map, newest);
}

int LocalWindowAdjustment::gather(VoMap* map, int* n_points, int* n_observations) {
  const int window = std::min(window_, map->keyframeCount());
  const int stamp = map->nextStamp();
  int n_pts = 0;
  int n_obs = 0;
  const int max_entries = static_cast<int>(observations_.size());
  for (int c = 0; c < window; ++c) {
    const int age = window - 1 - c;  // camera 0 is the oldest keyframe of the window: fixed
    const Keyframe& kf = map->keyframe(age);
    R_cam_world_[c] = kf.R_cam_world;
    p_world_in_cam_m_[c] = kf.p_world_in_cam_m;
    for (std::size_t f = 0; f < kf.map_point.size() && n_obs < max_entries; ++f) {
      const int m = kf.map_point[f];
      if (m < 0) continue;
      MapPoint& point = map->point(m);
      if (!point.alive) continue;
      if (point.visit_stamp != stamp) {
        point.visit_stamp = stamp;
        point.ba_index = n_pts;
        p_in_world_m_[n_pts] = point.p_in_world_m;
        point_id_[n_pts] = m;
        ++n_pts;
      }
      BaObservation& o = observations_[n_obs];
      o.camera = c;
      o.point = point.ba_index;
      o.uv_px = {kf.features[f].u_px, kf.features[f].v_px};
      o.u_right_px = kf.u_right_px[f];
      o.sigma_px = level_sigma_px_[kf.features[f].level];
      source_age_[n_obs] = age;
      source_feature_[n_obs] = static_cast<int>(f);
      ++n_obs;
    }
  }
  *n_points = n_pts;
  *n_observations = n_obs;
  return window;
}

void LocalWindowAdjustment::writeBack(int window, int n_points, int n_observations, VoMap* map,
                                      OrbFrame* newest) const {
  for (int c = 1; c < window; ++c) {
    Keyframe& kf = map->keyframe(window - 1 - c);
    kf.R_cam_world = R_cam_world_[c];
    kf.p_world_in_cam_m = p_world_in_cam_m_[c];
  }
  for (int j = 0; j < n_points; ++j) map->point(point_id_[j]).p_in_world_m = p_in_world_m_[j];
  for (int k = 0; k < n_observations; ++k) {
    if (!outlier_[k]) continue;
    Keyframe& kf = map->keyframe(source_age_[k]);
    const int f = source_feature_[k];
    const int m = kf.map_point[f];
    if (m < 0) continue;
    kf.map_point[f] = -1;
    if (source_age_[k] == 0) newest->map_point[f] = -1;  // the newest keyframe is this frame
    map->releaseReference(m);
  }
  const Keyframe& kf = map->keyframe(0);
  newest->pose.R_cam_world = kf.R_cam_world;
  newest->pose.p_world_in_cam_m = kf.p_world_in_cam_m;
}

}  // namespace deepnav
