#include "vision/orbvo/vo_map.h"

#include "vision/orbvo/keyframe_thumbnail.h"

namespace deepnav {

bool VoMap::init(int max_keyframes, int max_features_per_keyframe, int max_map_points) {
  if (max_keyframes < 2 || max_features_per_keyframe < 1 || max_map_points < 1) return false;
  keyframes_.assign(max_keyframes, Keyframe());
  for (Keyframe& kf : keyframes_) {
    kf.features.reserve(max_features_per_keyframe);
    kf.descriptors.reserve(max_features_per_keyframe);
    kf.u_right_px.reserve(max_features_per_keyframe);
    kf.map_point.reserve(max_features_per_keyframe);
    kf.thumbnail.assign(kThumbnailSize, 0.0f);
  }
  points_.assign(max_map_points, MapPoint());
  free_points_.reserve(max_map_points);
  clear();
  return true;
}

void VoMap::clear() {
  for (Keyframe& kf : keyframes_) {
    kf.id = -1;
    kf.features.clear();
    kf.descriptors.clear();
    kf.u_right_px.clear();
    kf.map_point.clear();
  }
  newest_slot_ = -1;
  keyframe_count_ = 0;
  free_points_.clear();
  for (int id = static_cast<int>(points_.size()) - 1; id >= 0; --id) {
    points_[id] = MapPoint();
    free_points_.push_back(id);
  }
  live_points_ = 0;
}

Keyframe& VoMap::pushKeyframe() {
  const int n = static_cast<int>(keyframes_.size());
  newest_slot_ = (newest_slot_ + 1) % n;
  Keyframe& kf = keyframes_[newest_slot_];
  if (keyframe_count_ == n) {
    for (int id : kf.map_point) {
      if (id >= 0) releaseReference(id);
    }
  } else {
    ++keyframe_count_;
  }
  kf.id = next_keyframe_id_++;
  kf.features.clear();
  kf.descriptors.clear();
  kf.u_right_px.clear();
  kf.map_point.clear();
  kf.tracked = 0;
  return kf;
}

int VoMap::createPoint(const Eigen::Vector3d& p_in_world_m, const OrbDescriptor& descriptor,
                       int level) {
  if (free_points_.empty()) return -1;
  const int id = free_points_.back();
  free_points_.pop_back();
  MapPoint& p = points_[id];
  p = MapPoint();
  p.p_in_world_m = p_in_world_m;
  p.descriptor = descriptor;
  p.level = level;
  p.references = 1;
  p.alive = true;
  ++live_points_;
  return id;
}

void VoMap::releaseReference(int id) {
  MapPoint& p = points_[id];
  if (!p.alive) return;
  if (--p.references > 0) return;
  p.alive = false;
  free_points_.push_back(id);
  --live_points_;
}

}  // namespace deepnav
