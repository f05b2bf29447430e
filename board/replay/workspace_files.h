#pragma once
#include <string>

#include <Eigen/Geometry>

#include "vision/pipeline/workspace_model.h"

namespace deepnav {

// A saved workspace, the output of stage 1 that lets a later dive (or a restart) start in stage 2:
//   DIR/workspace.bt    the OctoMap of the workspace (binary .bt),
//   DIR/workspace.yaml  T_panel_map: pose of the map's frame in the panel frame (position m, quaternion
//                       xyzw), with the map's resolution and voxel count for the reader.
// The panel pose itself is not saved: a new dive has a new odometry frame, and the markers fix the panel
// in it again; the map follows the panel.
bool saveWorkspace(const std::string& dir, const WorkspaceModel& model, const Eigen::Isometry3d& T_odom_panel,
                   std::string* error);
bool loadWorkspace(const std::string& dir, WorkspaceModel* model, std::string* error);

}  // namespace deepnav
