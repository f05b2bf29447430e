#pragma once
#include <Eigen/Geometry>

#include "nav/types/nav_solution.h"

namespace deepnav {

// What the navigation side tells the vision worker about one stereo pair: the stage, and where the
// camera was at the pair's capture time (from the filter's pose history), so stage 1 can place the
// pair's cloud in the workspace map and stage 2 can filter it by the map.
struct VisionContext {
  NavStage stage = NavStage::kInit;
  bool has_pose = false;
  Eigen::Isometry3d T_odom_cam = Eigen::Isometry3d::Identity();  // left camera at capture
  bool panel_fixed = false;
  Eigen::Isometry3d T_odom_panel = Eigen::Isometry3d::Identity();
};

}  // namespace deepnav
