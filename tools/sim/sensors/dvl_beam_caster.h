#pragma once
#include <cstdint>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tools/sim/render/fish_school.h"
#include "tools/sim/render/scene.h"
#include "tools/sim/scenario.h"

namespace deepnav::sim {

// What one DVL beam meets.
struct DvlEcho {
  double range_m = 0.0;                                        // slant range to the first surface
  Eigen::Vector3d v_target_in_odom_mps = Eigen::Vector3d::Zero();  // its velocity (a fish moves)
  bool fish = false;
};

// DVL beams cast against the world the renderer draws (render/scene.h: seabed relief, panel faces,
// fixtures, fish) instead of a flat seabed. The scene is built once (its textures too, ~150 ms), from
// the same scenario and seed as the renderer's, so the DVL sees the relief and fish the cameras see.
class DvlBeamCaster {
 public:
  bool init(const Scenario& scenario, std::uint64_t scene_seed, std::string* error);
  // First surface along p + t d (odometry frame, d unit) with t in (0, max_range_m], at time t_s (the
  // fish move); false when the beam meets nothing within range.
  bool cast(const Eigen::Vector3d& p_in_odom_m, const Eigen::Vector3d& d_in_odom, double t_s, double max_range_m,
            DvlEcho* echo);

 private:
  Eigen::Vector3d fishVelocityInOdom_mps(int fish, double t_s) const;

  Scene scene_;
  FishSchool fish_;  // the scene's fish again, for their velocities
  int first_fish_ = 0;
  double scene_t_s_ = -1.0;
  Eigen::Isometry3d T_panel_odom_ = Eigen::Isometry3d::Identity();
};

}  // namespace deepnav::sim
