#pragma once
#include <vector>

#include "vision/orbvo/feature_grid.h"
#include "vision/orbvo/orb_frame.h"
#include "vision/orbvo/projection_search.h"
#include "vision/orbvo/stereo_rig.h"
#include "vision/orbvo/vo_map.h"

namespace deepnav {

// Tracking's data association: map points projected into the current frame by a pose and matched
// to its features in a window around the projection (searchNearProjection), the best descriptor
// distance winning a feature. Two sources: the previous frame's map points (by the predicted pose)
// and the points of the local keyframes, plus those of a relocalisation anchor and its neighbours
// while it is recent (by the tracked pose). Sized in init(); the searches do not allocate.
class MapPointSearch {
 public:
  // level_scale[l]: scale of pyramid level l. local_keyframes: the newest keyframes searched.
  bool init(const StereoRig& rig, const std::vector<double>& level_scale, int local_keyframes,
            const ProjectionSearchConfig& frame_search, const ProjectionSearchConfig& map_search,
            int capacity);

  // Indexes the current frame's features; before the searches of each pair.
  void index(const OrbFrame& cur) { grid_.build(cur.features); }

  // The previous frame's map points, projected by `predicted`, in a window of radius_px (level 0).
  // Returns the number of the current frame's associations.
  int searchPreviousFrame(const OrbFrame& prev, const CameraPoseEstimate& predicted,
                          double radius_px, VoMap* map, OrbFrame* cur);

  // The local keyframes' points (and the anchor's) not matched yet, projected by `pose`. Returns
  // the number of the current frame's associations.
  int searchLocalMap(const CameraPoseEstimate& pose, VoMap* map, OrbFrame* cur);

  // Keeps the keyframe `keyframe_id` and its neighbours in the local map until the newest keyframe
  // id reaches until_keyframe_id (after a relocalisation against it).
  void anchorAt(int keyframe_id, int until_keyframe_id) {
    anchor_keyframe_id_ = keyframe_id;
    anchor_until_keyframe_id_ = until_keyframe_id;
  }
  void clearAnchor() { anchor_keyframe_id_ = -1; }

 private:
  void searchKeyframePoints(const Keyframe& kf, const CameraPoseEstimate& pose, int stamp,
                            VoMap* map, OrbFrame* cur) const;
  bool insideImage(const Eigen::Vector2d& uv_px) const;
  void matchProjection(int m, const CameraPoseEstimate& pose, int level,
                       const OrbDescriptor& descriptor, const ProjectionSearchConfig& search,
                       int stamp, VoMap* map, OrbFrame* cur) const;

  StereoRig rig_{};
  std::vector<double> level_scale_;
  int local_keyframes_ = 0;
  ProjectionSearchConfig frame_search_{};
  ProjectionSearchConfig map_search_{};
  FeatureGrid grid_;
  int anchor_keyframe_id_ = -1;  // keyframe found by the last relocalisation, kept in the local map
  int anchor_until_keyframe_id_ = -1;
};

}  // namespace deepnav
