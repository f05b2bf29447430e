#pragma once
#include <cstdint>
#include <iosfwd>
#include <string>

#include <Eigen/Geometry>

#include "vision/cloud/organized_cloud.h"
#include "vision/workspace/workspace_map.h"

namespace deepnav {

struct WorkspaceBuildConfig {
  WorkspaceConfig map;
  int insert_every_n_frames = 5;  // stage 1: one pair in n is matched densely and inserted (2 Hz at 10 Hz)
  int min_frames = 20;            // map ready: at least this many clouds inserted ...
  int min_voxels = 1500;          // ... and this many occupied voxels
};

// The stage-1 workspace map of the paper and the frame it lives in. A map built in this run lives in the
// odometry frame; a map restored from a saved workspace lives in the frame it was built in (map frame
// M'), tied to the panel by T_panel_map, and is placed in this run's odom through the panel pose once the
// markers have fixed it again.
class WorkspaceModel {
 public:
  bool init(const WorkspaceBuildConfig& config, std::string* error);

  // Stage 1: inserts one cloud (camera frame) taken at T_odom_cam. Only for a map of this run.
  bool insert(const OrganizedCloud& cloud, const Eigen::Isometry3d& T_odom_cam);
  bool wantsFrame(std::uint64_t frame_index) const {
    return !restored_ && !map_.frozen() && frame_index % static_cast<std::uint64_t>(config_.insert_every_n_frames) == 0;
  }

  bool ready() const { return restored_ || (frames_ >= config_.min_frames && voxels_ >= config_.min_voxels); }
  // Stage 2: freezes the map (builds the lookup) on first use, then removes the points of *cloud (camera
  // frame at T_odom_cam) far from the map. -1 when the map cannot be placed (restored map, panel unknown).
  int filter(const Eigen::Isometry3d& T_odom_cam, bool panel_fixed, const Eigen::Isometry3d& T_odom_panel,
             OrganizedCloud* cloud);

  // The same with the camera pose given in the map's own frame (tools: the map of the same dive).
  int filterInMapFrame(const Eigen::Isometry3d& T_map_cam, OrganizedCloud* cloud);

  // Saved workspace: the octree (.bt stream) and T_panel_map. save() needs the panel pose of this run
  // when the map was built here.
  bool save(std::ostream& octree_out, const Eigen::Isometry3d& T_odom_panel, Eigen::Isometry3d* T_panel_map) const;
  bool restore(std::istream& octree_in, const Eigen::Isometry3d& T_panel_map, std::string* error);

  int frames() const { return frames_; }
  int voxels() const { return voxels_; }
  bool restored() const { return restored_; }
  const WorkspaceMap& map() const { return map_; }

 private:
  WorkspaceBuildConfig config_;
  WorkspaceMap map_;
  int frames_ = 0;
  int voxels_ = 0;
  bool restored_ = false;
  bool freeze_failed_ = false;
  Eigen::Isometry3d T_panel_map_ = Eigen::Isometry3d::Identity();
};

}  // namespace deepnav
