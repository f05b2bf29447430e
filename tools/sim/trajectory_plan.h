#pragma once
#include <vector>

#include "tools/sim/jet2.h"
#include "tools/sim/panel_geometry.h"

namespace deepnav::sim {

// One waypoint of a scripted dive (scenario key `trajectory.plan`): where the robot stands relative to
// the panel, reached from the previous waypoint in `move_s` and then held for `hold_s`. The robot stays
// on the superellipse x^4 + y^4 = a^4 (panel frame, a = half width + standoff) at polar angle
// `bearing_deg` (90: the left face, valves; 0: the front, grasping; -90: the right face, plain), so a
// move between two bearings goes around the panel like the built-in plan does.
struct PlanWaypoint {
  double bearing_deg = 90.0;    // polar angle of the robot in the panel frame
  double standoff_m = 1.5;      // distance from the face (a = half width + standoff)
  double depth_m = 998.5;       // robot depth, positive down
  double face_alignment = 0.75; // 0: optical axis at the panel centre; 1: along the face normal
  double move_s = 0.0;          // time to reach this waypoint from the previous one (0 for the first)
  double hold_s = 0.0;          // time held here before the next move

  bool operator==(const PlanWaypoint&) const = default;
};

// The nominal pose (planar position in P, depth, yaw in P) of a scripted plan at time t. Each quantity
// is the first waypoint's value plus, per move, the step to the next waypoint times a quintic
// smootherstep over the move's interval: rest-to-rest, C2, with exact Jet2 derivatives.
struct PlanPose {
  Jet2 x, y, depth, yaw;
};

class TrajectoryPlan {
 public:
  // waypoints must be non-empty, with move_s > 0 after the first (checked by Trajectory::init).
  void init(const std::vector<PlanWaypoint>& waypoints, const PanelGeometry& panel);
  PlanPose poseAt(const Jet2& t) const;
  double duration_s() const { return duration_s_; }

 private:
  std::vector<PlanWaypoint> waypoints_;
  std::vector<double> move_start_s_;  // start of the move into waypoint i (i >= 1)
  double half_width_m_ = 1.0;
  double duration_s_ = 0.0;
};

}  // namespace deepnav::sim
