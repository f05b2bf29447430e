#pragma once
#include <Eigen/Geometry>

#include "tools/sim/camera_tick.h"
#include "tools/sim/scenario.h"

namespace deepnav::sim {

// The panel frame P in the odometry (scene) frame: footprint centre on the seabed, x along the front
// face's normal (yawed by panel.front_yaw_deg), z up.
Eigen::Isometry3d panelPoseInOdom(const Scenario& scenario);

// A camera tick of the scenario's rig (right camera baseline_m to the left camera's right, same
// orientation) with the left camera distance_m in front of face `face` (0 valves, 1 grasping, 2 plain),
// at s_m along the face (to the right as seen from outside) and z_m above the seabed, looking along the
// face's inward normal, then turned left by yaw_deg and nose-down by pitch_deg. For tests and previews.
CameraTick tickFacingFace(const Scenario& scenario, int face, double distance_m, double s_m, double z_m,
                          double yaw_deg = 0.0, double pitch_deg = 0.0, TimeUs t_us = 0);

}  // namespace deepnav::sim
