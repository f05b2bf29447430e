#include "vision/orbvo/map_point_search.h"

#include <algorithm>

#include "vision/orbvo/stereo_projection.h"

namespace deepnav {
namespace {

constexpr double kMinProjectionDepthM = 0.05;
constexpr int kGridCellPx = 16;

}  // namespace

bool MapPointSearch::init(const StereoRig& rig, const std::vector<double>& level_scale,
                          int local_keyframes, const ProjectionSearchConfig& frame_search,
                          const ProjectionSearchConfig& map_search, int capacity) {
  rig_ = rig;
  level_scale_ = level_scale;
  local_keyframes_ = local_keyframes;
  frame_search_ = frame_search;
  map_search_ = map_search;
  anchor_keyframe_id_ = -1;
  anchor_until_keyframe_id_ = -1;
  return grid_.init(rig.width_px, rig.height_px, kGridCellPx, capacity);
}

bool MapPointSearch::insideImage(const Eigen::Vector2d& uv_px) const {
  return uv_px.x() >= 0.0 && uv_px.y() >= 0.0 && uv_px.x() <= rig_.width_px - 1.0 &&
         uv_px.y() <= rig_.height_px - 1.0;
}

int MapPointSearch::searchPreviousFrame(const OrbFrame& prev, const CameraPoseEstimate& predicted,
                                        double radius_px, VoMap* map, OrbFrame* cur) {
  const int stamp = map->nextStamp();
  ProjectionSearchConfig search = frame_search_;
  search.radius_px = radius_px;
  for (std::size_t i = 0; i < prev.map_point.size(); ++i) {
    const int m = prev.map_point[i];
    if (m < 0) continue;
    matchProjection(m, predicted, prev.features[i].level, prev.descriptors[i], search, stamp, map,
                    cur);
  }
  return cur->associationCount();
}

int MapPointSearch::searchLocalMap(const CameraPoseEstimate& pose, VoMap* map, OrbFrame* cur) {
  const int stamp = map->nextStamp();
  for (std::size_t j = 0; j < cur->map_point.size(); ++j) {
    const int m = cur->map_point[j];
    cur->available[j] = m < 0;
    if (m >= 0) map->point(m).visit_stamp = stamp;
  }
  const int local = std::min(local_keyframes_, map->keyframeCount());
  for (int age = 0; age < local; ++age) searchKeyframePoints(map->keyframe(age), pose, stamp, map, cur);
  if (anchor_keyframe_id_ >= 0 && map->keyframeCount() > 0) {
    const int newest_id = map->keyframe(0).id;
    if (newest_id >= anchor_until_keyframe_id_) {
      anchor_keyframe_id_ = -1;
    } else {
      constexpr int kAnchorNeighbours = 2;
      for (int id = anchor_keyframe_id_ - kAnchorNeighbours;
           id <= anchor_keyframe_id_ + kAnchorNeighbours; ++id) {
        const int age = newest_id - id;
        if (age < local || age >= map->keyframeCount() || map->keyframe(age).id != id) continue;
        searchKeyframePoints(map->keyframe(age), pose, stamp, map, cur);
      }
    }
  }
  return cur->associationCount();
}

void MapPointSearch::searchKeyframePoints(const Keyframe& kf, const CameraPoseEstimate& pose,
                                          int stamp, VoMap* map, OrbFrame* cur) const {
  for (const int m : kf.map_point) {
    if (m < 0) continue;
    const MapPoint& point = map->point(m);
    matchProjection(m, pose, point.level, point.descriptor, map_search_, stamp, map, cur);
  }
}

// Map point m, unless dead or visited by this search (stamp), projected by `pose` and matched near its
// projection with the query's level and descriptor; the match takes the feature unless it holds a
// closer one.
void MapPointSearch::matchProjection(int m, const CameraPoseEstimate& pose, int level,
                                     const OrbDescriptor& descriptor,
                                     const ProjectionSearchConfig& search, int stamp, VoMap* map,
                                     OrbFrame* cur) const {
  MapPoint& point = map->point(m);
  if (!point.alive || point.visit_stamp == stamp) return;
  point.visit_stamp = stamp;
  const Eigen::Vector3d p_in_cam_m = pose.R_cam_world * point.p_in_world_m + pose.p_world_in_cam_m;
  if (p_in_cam_m.z() < kMinProjectionDepthM) return;
  const Eigen::Vector2d uv = projectLeft(rig_, p_in_cam_m);
  if (!insideImage(uv)) return;
  const ProjectionMatch match =
      searchNearProjection(grid_, cur->features, cur->descriptors, cur->available,
                           level_scale_.data(), uv, level, descriptor, search);
  if (match.index < 0 || match.distance >= cur->match_distance[match.index]) return;
  cur->map_point[match.index] = m;
  cur->match_distance[match.index] = match.distance;
}

}  // namespace deepnav

