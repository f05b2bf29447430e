#pragma once
#include <vector>

#include "tools/sim/trajectory_plan.h"

namespace deepnav::sim {

// The dive plan (scenario key `trajectory`). The ROV holds far from the panel, approaches the left face
// radially while descending to the circling depth, dwells facing it, moves around the front-left corner
// to face the front, dwells, moves around the front-right corner to face the right face, and dwells.
// Small sinusoidal disturbances ride on top. Defaults make a 120 s dive.
struct TrajectoryConfig {
  double standoff_m = 1.5;          // distance from a face to the robot while circling
  double start_distance_m = 8.0;    // distance from the left face at the start
  double start_depth_m = 998.0;     // robot depth at the start (positive down)
  double circle_depth_m = 998.5;    // robot depth while circling (constant)
  double start_hold_s = 4.0;        // hover before the approach
  double approach_s = 26.0;         // duration of the approach
  double dwell_s = 12.0;            // time facing each face
  double traverse_s = 27.0;         // time to move around one corner to the next face
  double face_alignment = 0.75;     // 0: optical axis at the panel centre; 1: along the face normal
  double surge_amplitude_m = 0.05;  // peak position disturbances along the nominal body axes
  double sway_amplitude_m = 0.05;
  double heave_amplitude_m = 0.03;
  double roll_amplitude_deg = 1.5;  // peak attitude disturbances
  double pitch_amplitude_deg = 1.5;
  double yaw_amplitude_deg = 1.0;
  double disturbance_period_s = 9.0;  // period of the slowest disturbance sinusoid
  // A scripted dive instead of the built-in plan above (its standoff, start, depths and durations are
  // then unused; the disturbances still apply). Empty: the built-in plan.
  std::vector<PlanWaypoint> plan;

  bool operator==(const TrajectoryConfig&) const = default;
};

}  // namespace deepnav::sim
