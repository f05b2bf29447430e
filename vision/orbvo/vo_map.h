#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "nav/types/time.h"
#include "vision/orbvo/orb_feature.h"

namespace deepnav {

// A 3-D point of the odometry's world frame W (the left camera frame of the first keyframe).
struct MapPoint {
  Eigen::Vector3d p_in_world_m = Eigen::Vector3d::Zero();
  OrbDescriptor descriptor{};  // from the newest keyframe that saw it
  int level = 0;               // pyramid level of that observation
  int references = 0;          // keyframe features pointing at it; 0 frees the point
  int visit_stamp = -1;        // scratch: the last search that considered it
  int ba_index = -1;           // scratch: index inside the local bundle adjustment
  bool alive = false;
};

// A stored stereo frame: its pose, its left features with their stereo columns and map points.
struct Keyframe {
  int id = -1;
  TimeUs t_us = 0;
  Eigen::Matrix3d R_cam_world = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_world_in_cam_m = Eigen::Vector3d::Zero();
  std::vector<OrbFeature> features;
  std::vector<OrbDescriptor> descriptors;
  std::vector<float> u_right_px;  // < 0: no stereo match
  std::vector<int> map_point;     // < 0: none
  std::vector<float> thumbnail;   // kThumbnailSize values (keyframe_thumbnail.h)
  int tracked = 0;                // map points tracked by the frame it was made from
};

// Keyframes in a ring (the oldest is evicted when full) and a fixed pool of map points with
// reference counts. Everything is allocated in init(); no member allocates afterwards.
class VoMap {
 public:
  bool init(int max_keyframes, int max_features_per_keyframe, int max_map_points);
  void clear();

  int keyframeCount() const { return keyframe_count_; }
  // age 0 is the newest keyframe, keyframeCount() - 1 the oldest.
  Keyframe& keyframe(int age) { return keyframes_[slotOf(age)]; }
  const Keyframe& keyframe(int age) const { return keyframes_[slotOf(age)]; }

  // A fresh keyframe slot (features cleared) that becomes the newest; evicts the oldest when full.
  Keyframe& pushKeyframe();

  int mapPointCount() const { return live_points_; }
  MapPoint& point(int id) { return points_[id]; }
  const MapPoint& point(int id) const { return points_[id]; }

  // New point with one reference; -1 when the pool is full.
  int createPoint(const Eigen::Vector3d& p_in_world_m, const OrbDescriptor& descriptor, int level);
  void addReference(int id) { ++points_[id].references; }
  void releaseReference(int id);

  // A fresh stamp for the visit_stamp scratch field.
  int nextStamp() { return ++stamp_; }

 private:
  int slotOf(int age) const {
    const int n = static_cast<int>(keyframes_.size());
    return ((newest_slot_ - age) % n + n) % n;
  }

  std::vector<Keyframe> keyframes_;
  int newest_slot_ = -1;
  int keyframe_count_ = 0;
  int next_keyframe_id_ = 0;
  std::vector<MapPoint> points_;
  std::vector<int> free_points_;
  int live_points_ = 0;
  int stamp_ = 0;
};

}  // namespace deepnav
