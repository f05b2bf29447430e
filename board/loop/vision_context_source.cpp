#include "board/loop/vision_context_source.h"

namespace deepnav {

void VisionContextSource::push(const NavFeedback& f) {
  if (f.has_pose) poses_.push(f.t_us, f.p_robot_in_odom_m, f.q_odom_robot);
  latest_ = f;
}

VisionContext VisionContextSource::contextAt(TimeUs t_us) const {
  VisionContext c;
  c.stage = latest_.stage;
  c.panel_fixed = latest_.panel_fixed;
  c.T_odom_panel = latest_.T_odom_panel;
  Eigen::Isometry3d T_odom_robot;
  if (poses_.poseAt(t_us, &T_odom_robot)) {
    c.has_pose = true;
  } else if (latest_.has_pose && t_us >= latest_.t_us && t_us - latest_.t_us <= kMaxAheadUs) {
    T_odom_robot = Eigen::Isometry3d::Identity();
    T_odom_robot.linear() = latest_.q_odom_robot.toRotationMatrix();
    T_odom_robot.translation() = latest_.p_robot_in_odom_m;
    c.has_pose = true;
  }
  if (c.has_pose) c.T_odom_cam = T_odom_robot * T_robot_cam_;
  return c;
}

}  // namespace deepnav
