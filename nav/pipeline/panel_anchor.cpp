#include "nav/pipeline/panel_anchor.h"

namespace deepnav {

bool clonePoseInOdom(const FilterState& s, std::uint32_t id, Eigen::Isometry3d* T_odom_clone) {
  for (int i = 0; i < s.n_clones; ++i) {
    const PoseClone& c = s.clones[static_cast<std::size_t>(i)];
    if (c.id != id) continue;
    T_odom_clone->setIdentity();
    T_odom_clone->linear() = c.q_odom_robot.normalized().toRotationMatrix();
    T_odom_clone->translation() = c.p_robot_in_odom_m;
    return true;
  }
  return false;
}

void PanelAnchor::reset() {
  anchored_ = false;
  tied_ = false;
  clone_id_ = kFirstCloneId;
  T_odom_panel_at_anchor_.setIdentity();
  last_T_odom_panel_.setIdentity();
  T_anchor_panel_.setIdentity();
  counters_ = PanelAnchorCounters{};
}

void PanelAnchor::anchor(TimeUs t_us, const Eigen::Isometry3d& T_odom_panel, Ekf* ekf) {
  // A fresh id per anchor: a clone request still queued under the old id can never be mistaken for it.
  if (counters_.anchors > 0) ++clone_id_;
  ++counters_.anchors;
  anchored_ = true;
  tied_ = false;
  T_odom_panel_at_anchor_ = T_odom_panel;
  last_T_odom_panel_ = T_odom_panel;
  ekf->clonePose(t_us, clone_id_);
  tieToClone(*ekf);
}

bool PanelAnchor::tieToClone(const Ekf& ekf) {
  Eigen::Isometry3d T_odom_anchor;
  if (!clonePoseInOdom(ekf.state(), clone_id_, &T_odom_anchor)) return false;
  T_anchor_panel_ = T_odom_anchor.inverse() * T_odom_panel_at_anchor_;
  tied_ = true;
  return true;
}

bool PanelAnchor::ready(const Ekf& ekf) {
  if (!anchored_) return false;
  if (!tied_) {
    if (tieToClone(ekf)) return true;
    ++counters_.pending;
    return false;
  }
  Eigen::Isometry3d T_odom_anchor;
  if (clonePoseInOdom(ekf.state(), clone_id_, &T_odom_anchor)) {
    last_T_odom_panel_ = T_odom_anchor * T_anchor_panel_;
    return true;
  }
  // Lost (a filter reset drops every clone): the panel stays where the anchor last had it.
  ++counters_.losses;
  anchored_ = false;
  return false;
}

Eigen::Isometry3d PanelAnchor::T_odom_panel(const Ekf& ekf) const {
  Eigen::Isometry3d T_odom_anchor;
  if (tied_ && clonePoseInOdom(ekf.state(), clone_id_, &T_odom_anchor)) return T_odom_anchor * T_anchor_panel_;
  return last_T_odom_panel_;
}

}  // namespace deepnav
