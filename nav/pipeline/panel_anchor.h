#pragma once
#include <cstdint>

#include <Eigen/Geometry>

#include "nav/ekf/ekf.h"
#include "nav/types/time.h"

namespace deepnav {

struct PanelAnchorCounters {
  std::uint32_t anchors = 0;    // clones taken for the panel (the first, then one per loss)
  std::uint32_t losses = 0;     // the filter dropped the anchor clone (reset, IMU gap restart)
  std::uint32_t pending = 0;    // marker images skipped while the anchor clone was queued
};

// The fixed panel held in the filter. Stage 1 measures the panel from the robot's own estimate, so the
// panel's error in odom is the robot's error at that time (dead-reckoning drift, the compass's residual
// bias): one error shared by every later marker pose. Fusing those poses in odom as if the panel were
// exact pins the robot to a frame that is itself off, with a covariance of millimetres: the filter
// becomes inconsistent in odom and fights the compass and the DVL, whose errors differ.
// Instead the robot pose at the fix is cloned into the filter (a stochastic clone that is never
// released, nav/ekf/stochastic_clone.h) and the panel is kept relative to it, T_anchor_panel constant;
// each marker then gives the relative pose T_anchor_robot = T_anchor_panel T_panel_robot, fused against
// the clone (Ekf::fuseRelativePose). The clone carries the robot's covariance at the fix and its
// correlation with the rest of the state, so the panel's own uncertainty in odom stays in the filter and
// the compass, DVL and VO refine the panel together with the robot. The panel in odom follows the clone:
//   T_odom_panel = T_odom_anchor T_anchor_panel.
// No allocation.
class PanelAnchor {
 public:
  // Well above the visual odometry's clone ids (nav/pipeline/vo_fusion.h counts from 1 per pair).
  static constexpr std::uint32_t kFirstCloneId = 0xFA000000u;

  void reset();

  // Clones the filter's pose at t_us and ties the panel T_odom_panel to it. Used at the first marker
  // image after the fix and whenever the clone was lost (with the last panel pose the anchor gave).
  void anchor(TimeUs t_us, const Eigen::Isometry3d& T_odom_panel, Ekf* ekf);

  // True when the anchor clone is in the filter's state (a queued clone becomes ready once the IMU
  // reaches its time; its T_anchor_panel is then taken from the clone the filter actually holds).
  bool ready(const Ekf& ekf);
  bool anchored() const { return anchored_; }

  std::uint32_t cloneId() const { return clone_id_; }
  const Eigen::Isometry3d& T_anchor_panel() const { return T_anchor_panel_; }
  // The panel in odom through the current clone; the last one seen through it when the clone is gone
  // (or, before the queued clone is tied, the pose it was anchored with).
  Eigen::Isometry3d T_odom_panel(const Ekf& ekf) const;
  const PanelAnchorCounters& counters() const { return counters_; }

 private:
  bool tieToClone(const Ekf& ekf);

  bool anchored_ = false;  // a clone was requested and not lost since
  bool tied_ = false;      // T_anchor_panel_ is relative to the clone the filter holds
  std::uint32_t clone_id_ = kFirstCloneId;
  Eigen::Isometry3d T_odom_panel_at_anchor_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d T_anchor_panel_ = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d last_T_odom_panel_ = Eigen::Isometry3d::Identity();
  PanelAnchorCounters counters_;
};

// The filter's pose of clone `id`, false when it holds no such clone.
bool clonePoseInOdom(const FilterState& s, std::uint32_t id, Eigen::Isometry3d* T_odom_clone);

}  // namespace deepnav
