#include "tools/sim/sensors/dvl_beam_caster.h"

#include "tools/sim/render/panel_knowledge.h"

namespace deepnav::sim {

namespace {
constexpr float kMinRange_m = 1e-3f;  // the transducer face itself
constexpr double kFishVelocityStep_s = 0.01;  // central difference of the fish path (smooth, ~0.4 m/s)
}  // namespace

bool DvlBeamCaster::init(const Scenario& scenario, std::uint64_t scene_seed, std::string* error) {
  const MarkerLayout layout = defaultMarkerLayout();
  if (!scene_.init(scenario, makePanelDescription(scenario, layout), layout.quiet_zone_m, scene_seed, error))
    return false;
  // Scene::addFish draws the school from the same arguments and appends one primitive per fish, last.
  fish_.init(scenario.water.fish_count, scenario.panel.half_width_m, scenario.trajectory.standoff_m, scene_seed);
  first_fish_ = static_cast<int>(scene_.primitives().size()) - scenario.water.fish_count;
  T_panel_odom_ = scene_.T_odom_panel().inverse();
  scene_t_s_ = -1.0;
  return true;
}

bool DvlBeamCaster::cast(const Eigen::Vector3d& p_in_odom_m, const Eigen::Vector3d& d_in_odom, double t_s,
                         double max_range_m, DvlEcho* echo) {
  if (t_s != scene_t_s_) {
    scene_.setTime(t_s);
    scene_t_s_ = t_s;
  }
  const Eigen::Vector3f o = (T_panel_odom_ * p_in_odom_m).cast<float>();
  const Eigen::Vector3f d = (T_panel_odom_.linear() * d_in_odom).cast<float>();
  SceneHit hit;
  if (!scene_.intersect(o, d, kMinRange_m, static_cast<float>(max_range_m), &hit)) return false;
  echo->range_m = hit.t;
  echo->fish = hit.primitive >= first_fish_;
  echo->v_target_in_odom_mps =
      echo->fish ? fishVelocityInOdom_mps(hit.primitive - first_fish_, t_s) : Eigen::Vector3d::Zero();
  return true;
}

Eigen::Vector3d DvlBeamCaster::fishVelocityInOdom_mps(int fish, double t_s) const {
  Eigen::Matrix3f R;
  Eigen::Vector3f before, after;
  fish_.poseAt(fish, t_s - kFishVelocityStep_s, &R, &before);
  fish_.poseAt(fish, t_s + kFishVelocityStep_s, &R, &after);
  const Eigen::Vector3d v_in_panel = (after - before).cast<double>() / (2.0 * kFishVelocityStep_s);
  return T_panel_odom_.linear().transpose() * v_in_panel;
}

}  // namespace deepnav::sim
