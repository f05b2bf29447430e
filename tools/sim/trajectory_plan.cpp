#include "tools/sim/trajectory_plan.h"

#include <numbers>

#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {

constexpr double kPi = std::numbers::pi;

// A quantity that steps from waypoint to waypoint: value_0 + sum_i (value_i - value_i-1) s_i(t), with
// s_i the smootherstep over move i.
template <typename Field>
Jet2 blended(const std::vector<PlanWaypoint>& w, const std::vector<double>& start_s, const Jet2& t, Field field) {
  Jet2 sum = Jet2::constant(field(w[0]));
  for (std::size_t i = 1; i < w.size(); ++i) {
    const double step = field(w[i]) - field(w[i - 1]);
    if (step == 0.0) continue;
    sum = sum + step * smootherstep((t - start_s[i]) * (1.0 / w[i].move_s));
  }
  return sum;
}

}  // namespace

void TrajectoryPlan::init(const std::vector<PlanWaypoint>& waypoints, const PanelGeometry& panel) {
  waypoints_ = waypoints;
  half_width_m_ = panel.half_width_m;
  move_start_s_.assign(waypoints.size(), 0.0);
  double t_s = waypoints.empty() ? 0.0 : waypoints[0].hold_s;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    move_start_s_[i] = t_s;
    t_s += waypoints[i].move_s + waypoints[i].hold_s;
  }
  duration_s_ = t_s;
}

PlanPose TrajectoryPlan::poseAt(const Jet2& t) const {
  const Jet2 theta =
      kDegToRad * blended(waypoints_, move_start_s_, t, [](const PlanWaypoint& w) { return w.bearing_deg; });
  const Jet2 standoff = blended(waypoints_, move_start_s_, t, [](const PlanWaypoint& w) { return w.standoff_m; });
  const Jet2 alignment =
      blended(waypoints_, move_start_s_, t, [](const PlanWaypoint& w) { return w.face_alignment; });
  const Jet2 a = half_width_m_ + standoff;

  // Superellipse in polar form (as Trajectory::nominalInPanel): cos^4 + sin^4 >= 1/2, the power is smooth;
  // the normal's angle from the radial direction is atan2(-sin(4 theta) / 4, cos^4 + sin^4).
  const Jet2 ct = cos(theta), st = sin(theta);
  const Jet2 c4s4 = ct * ct * ct * ct + st * st * st * st;
  const Jet2 rho = a * pow(c4s4, -0.25);
  const Jet2 normal_offset = atan2(-0.25 * sin(4.0 * theta), c4s4);

  PlanPose pose;
  pose.x = rho * ct;
  pose.y = rho * st;
  pose.depth = blended(waypoints_, move_start_s_, t, [](const PlanWaypoint& w) { return w.depth_m; });
  pose.yaw = theta + kPi + alignment * normal_offset;
  return pose;
}

}  // namespace deepnav::sim
