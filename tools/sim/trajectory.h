#pragma once
#include <string>

#include "tools/sim/kinematic_state.h"
#include "tools/sim/panel_geometry.h"
#include "tools/sim/trajectory_config.h"
#include "tools/sim/trajectory_plan.h"

namespace deepnav::sim {

struct Jet2;

// Where the robot is at any time of the dive: an analytic, C2-smooth path around the panel (see
// TrajectoryConfig for the plan). Position, yaw and the disturbances are written in Jet2, so velocity,
// acceleration and angular rate are exact derivatives of the pose, not finite differences.
//
// Shape: while circling, the robot stays on the superellipse x^4 + y^4 = a^4 (panel frame, a = half
// width + standoff). It is smooth (no curvature jump), passes exactly `standoff_m` in front of each face
// centre and about `standoff_m` + 0.1 m from the rounded corners. Yaw blends pointing at the panel
// centre with pointing along the superellipse's inward normal (`face_alignment`), so the forward cameras
// see the panel throughout.
class Trajectory {
 public:
  // Checks the configuration (depths, durations, standoff clear of the corners). gravity_mps2 > 0.
  bool init(const TrajectoryConfig& config, const PanelGeometry& panel, double odom_origin_depth_m,
            double gravity_mps2, std::string* error);

  // Exact state at trajectory time t_s (seconds since the start of the dive); any t_s is valid, the
  // plan holds its end state (plus disturbances) after the last dwell.
  KinematicState stateAt(double t_s) const;

  // Duration of the plan (built-in: hold + approach + 3 dwells + 2 traverses; scripted: its holds and
  // moves).
  double planDuration_s() const;

  const TrajectoryConfig& config() const { return config_; }
  const PanelGeometry& panel() const { return panel_; }

 private:
  struct PlanarPose;
  PlanarPose nominalInPanel(const Jet2& t) const;

  bool checkPlan(std::string* error) const;

  TrajectoryConfig config_;
  TrajectoryPlan plan_;
  PanelGeometry panel_;
  double odom_origin_depth_m_ = 0.0;
  double gravity_mps2_ = 9.80665;
};

}  // namespace deepnav::sim
