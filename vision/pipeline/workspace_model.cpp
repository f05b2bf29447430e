#include "vision/pipeline/workspace_model.h"

#include <istream>
#include <ostream>

namespace deepnav {

bool WorkspaceModel::init(const WorkspaceBuildConfig& config, std::string* error) {
  if (config.insert_every_n_frames < 1 || config.min_frames < 0 || config.min_voxels < 0 || !map_.init(config.map)) {
    if (error) *error = "vision: workspace map parameters rejected (vision.map_* keys)";
    return false;
  }
  config_ = config;
  frames_ = voxels_ = 0;
  restored_ = freeze_failed_ = false;
  return true;
}

bool WorkspaceModel::insert(const OrganizedCloud& cloud, const Eigen::Isometry3d& T_odom_cam) {
  if (restored_ || !map_.insert(cloud, T_odom_cam)) return false;
  ++frames_;
  voxels_ = static_cast<int>(map_.occupiedVoxelCount());
  return true;
}

int WorkspaceModel::filterInMapFrame(const Eigen::Isometry3d& T_map_cam, OrganizedCloud* cloud) {
  if (!map_.frozen()) {
    if (freeze_failed_) return -1;
    if (!map_.freeze()) {
      freeze_failed_ = true;  // too big for the lookup: stage 2 runs unfiltered rather than retrying
      return -1;
    }
  }
  return map_.filter(T_map_cam, cloud);
}

int WorkspaceModel::filter(const Eigen::Isometry3d& T_odom_cam, bool panel_fixed,
                           const Eigen::Isometry3d& T_odom_panel, OrganizedCloud* cloud) {
  if (!restored_) return filterInMapFrame(T_odom_cam, cloud);
  if (!panel_fixed) return -1;
  // T_map_cam = T_map_panel T_panel_odom T_odom_cam.
  return filterInMapFrame(T_panel_map_.inverse() * T_odom_panel.inverse() * T_odom_cam, cloud);
}

bool WorkspaceModel::save(std::ostream& octree_out, const Eigen::Isometry3d& T_odom_panel,
                          Eigen::Isometry3d* T_panel_map) const {
  *T_panel_map = restored_ ? T_panel_map_ : T_odom_panel.inverse();
  return map_.write(octree_out);
}

bool WorkspaceModel::restore(std::istream& octree_in, const Eigen::Isometry3d& T_panel_map, std::string* error) {
  if (!map_.read(octree_in)) {
    if (error) *error = "workspace: the octree stream is not a readable OctoMap .bt";
    return false;
  }
  restored_ = true;
  freeze_failed_ = false;
  T_panel_map_ = T_panel_map;
  voxels_ = static_cast<int>(map_.occupiedVoxelCount());
  frames_ = 0;
  return true;
}

}  // namespace deepnav
