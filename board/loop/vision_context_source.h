#pragma once
#include <Eigen/Geometry>

#include "nav/pipeline/pose_history.h"
#include "nav/types/nav_solution.h"
#include "vision/pipeline/vision_context.h"

namespace deepnav {

// What the nav loop tells the vision worker after each tick (NavCore::feedback()).
struct NavFeedback {
  TimeUs t_us = 0;
  bool has_pose = false;  // the filter is aligned
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  NavStage stage = NavStage::kInit;
  bool panel_fixed = false;
  Eigen::Isometry3d T_odom_panel = Eigen::Isometry3d::Identity();
};

// The vision worker's view of the navigation: its own copy of the recent trajectory (fed with the
// loop's feedback, on the worker's thread), answering "where was the camera at this capture time".
// A capture a little newer than the last tick (the worker can be ahead of the loop by one tick) takes
// the last pose. No allocation.
class VisionContextSource {
 public:
  static constexpr TimeUs kMaxAheadUs = 50'000;

  void init(const Eigen::Isometry3d& T_robot_cam) {
    T_robot_cam_ = T_robot_cam;
    poses_.clear();
    latest_ = NavFeedback{};
  }
  void push(const NavFeedback& f);
  VisionContext contextAt(TimeUs t_us) const;

 private:
  Eigen::Isometry3d T_robot_cam_ = Eigen::Isometry3d::Identity();
  PoseHistory poses_;
  NavFeedback latest_;
};

}  // namespace deepnav
