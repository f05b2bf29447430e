#include "tools/sim/trajectory.h"

#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "tools/sim/jet2.h"
#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {

constexpr double kPi = std::numbers::pi;

// Disturbances are sums of three sinusoids with incommensurate periods (ratios 1 : 0.61 : 0.37) and
// weights summing to 1, so the peak never exceeds the configured amplitude. Phases differ per channel so
// the channels are not correlated. They are fixed: the trajectory belongs to the scenario, not the seed.
constexpr std::array<double, 3> kPeriodRatio{1.0, 0.61, 0.37};
constexpr std::array<double, 3> kWeight{0.6, 0.3, 0.1};

Jet2 disturbance(const Jet2& t, double amplitude, double base_period_s, int channel) {
  Jet2 sum = Jet2::constant(0.0);
  for (int k = 0; k < 3; ++k) {
    const double omega = 2.0 * kPi / (base_period_s * kPeriodRatio[k]);
    const double phase = 1.3 * channel + 2.1 * k + 0.7 * channel * k;
    sum = sum + kWeight[k] * sin(omega * t + phase);
  }
  return amplitude * sum;
}

// Quintic blend from 0 to 1 over [t0, t0 + duration].
Jet2 blend(const Jet2& t, double t0, double duration) { return smootherstep((t - t0) * (1.0 / duration)); }

bool fail(std::string* error, const std::string& message) {
  if (error) *error = "trajectory: " + message;
  return false;
}

}  // namespace

// Nominal (undisturbed) pose in the panel frame: planar position, depth and yaw.
struct Trajectory::PlanarPose {
  Jet2 x, y, depth, yaw;
};

bool Trajectory::init(const TrajectoryConfig& config, const PanelGeometry& panel, double odom_origin_depth_m,
                      double gravity_mps2, std::string* error) {
  config_ = config;
  panel_ = panel;
  odom_origin_depth_m_ = odom_origin_depth_m;
  gravity_mps2_ = gravity_mps2;
  if (!(gravity_mps2 > 0.0)) return fail(error, "gravity must be > 0");
  if (!(config.standoff_m > 0.0)) return fail(error, "standoff_m must be > 0");
  if (!(config.start_distance_m >= config.standoff_m))
    return fail(error, "start_distance_m must be >= standoff_m");
  if (!(config.approach_s > 0.0 && config.traverse_s > 0.0 && config.dwell_s >= 0.0 &&
        config.start_hold_s >= 0.0))
    return fail(error, "approach_s and traverse_s must be > 0, dwell_s and start_hold_s >= 0");
  if (!(config.disturbance_period_s > 0.0)) return fail(error, "disturbance_period_s must be > 0");
  if (!(panel.half_width_m > panel.corner_radius_m && panel.corner_radius_m >= 0.0))
    return fail(error, "panel half_width_m must exceed corner_radius_m >= 0");
  if (!checkPlan(error)) return false;
  plan_.init(config.plan, panel);
  return true;
}

bool Trajectory::checkPlan(std::string* error) const {
  for (std::size_t i = 0; i < config_.plan.size(); ++i) {
    const PlanWaypoint& w = config_.plan[i];
    const std::string name = "plan[" + std::to_string(i) + "]";
    if (i > 0 && !(w.move_s > 0.0)) return fail(error, name + ".move_s must be > 0");
    if (!(w.hold_s >= 0.0)) return fail(error, name + ".hold_s must be >= 0");
    if (!(w.standoff_m > 0.0)) return fail(error, name + ".standoff_m must be > 0");
  }
  return true;
}

double Trajectory::planDuration_s() const {
  if (!config_.plan.empty()) return plan_.duration_s();
  return config_.start_hold_s + config_.approach_s + 3.0 * config_.dwell_s + 2.0 * config_.traverse_s;
}

Trajectory::PlanarPose Trajectory::nominalInPanel(const Jet2& t) const {
  if (!config_.plan.empty()) {
    const PlanPose scripted = plan_.poseAt(t);
    return {scripted.x, scripted.y, scripted.depth, scripted.yaw};
  }
  const TrajectoryConfig& c = config_;
  const double t_approach = c.start_hold_s;
  const double t_traverse1 = t_approach + c.approach_s + c.dwell_s;
  const double t_traverse2 = t_traverse1 + c.traverse_s + c.dwell_s;

  const Jet2 approach = blend(t, t_approach, c.approach_s);
  // Bearing of the robot in the panel frame: left face (+90 deg), then front (0), then right (-90 deg).
  const Jet2 theta = kPi / 2.0 - (kPi / 2.0) * blend(t, t_traverse1, c.traverse_s) -
                     (kPi / 2.0) * blend(t, t_traverse2, c.traverse_s);
  const double a_start = panel_.half_width_m + c.start_distance_m;
  const double a_circle = panel_.half_width_m + c.standoff_m;
  const Jet2 a = a_start + (a_circle - a_start) * approach;

  // Superellipse x^4 + y^4 = a^4 in polar form; cos^4 + sin^4 >= 1/2 so the power is smooth.
  const Jet2 ct = cos(theta), st = sin(theta);
  const Jet2 c4s4 = ct * ct * ct * ct + st * st * st * st;
  const Jet2 rho = a * pow(c4s4, -0.25);

  // Angle from the radial direction to the superellipse normal (gradient (x^3, y^3)):
  // atan2(-sin(4 theta) / 4, cos^4 + sin^4); zero at the face centres and the diagonals.
  const Jet2 s4 = sin(4.0 * theta);
  const Jet2 normal_offset = atan2(-0.25 * s4, c4s4);

  PlanarPose pose;
  pose.x = rho * ct;
  pose.y = rho * st;
  pose.depth = c.start_depth_m + (c.circle_depth_m - c.start_depth_m) * approach;
  pose.yaw = theta + kPi + c.face_alignment * normal_offset;
  return pose;
}

KinematicState Trajectory::stateAt(double t_s) const {
  const TrajectoryConfig& c = config_;
  const Jet2 t = Jet2::variable(t_s);
  const PlanarPose nominal = nominalInPanel(t);

  // Panel frame -> odometry frame.
  const double front_yaw = panel_.front_yaw_deg * kDegToRad;
  const double cf = std::cos(front_yaw), sf = std::sin(front_yaw);
  const Jet2 yaw_nominal = nominal.yaw + front_yaw;

  // Disturbances: surge/sway/heave along the nominal body axes, then roll/pitch/yaw.
  const double period = c.disturbance_period_s;
  const Jet2 surge = disturbance(t, c.surge_amplitude_m, period, 0);
  const Jet2 sway = disturbance(t, c.sway_amplitude_m, period, 1);
  const Jet2 heave = disturbance(t, c.heave_amplitude_m, period, 2);
  const Jet2 roll = disturbance(t, c.roll_amplitude_deg * kDegToRad, period, 3);
  const Jet2 pitch = disturbance(t, c.pitch_amplitude_deg * kDegToRad, period, 4);
  const Jet2 yaw = yaw_nominal + disturbance(t, c.yaw_amplitude_deg * kDegToRad, period, 5);

  const Jet2 cy = cos(yaw_nominal), sy = sin(yaw_nominal);
  const Jet2 x = panel_.centre_in_odom_m[0] + cf * nominal.x - sf * nominal.y + cy * surge - sy * sway;
  const Jet2 y = panel_.centre_in_odom_m[1] + sf * nominal.x + cf * nominal.y + sy * surge + cy * sway;
  const Jet2 z = (odom_origin_depth_m_ - nominal.depth) + heave;

  KinematicState s;
  s.t_s = t_s;
  s.p_robot_in_odom_m = {x.v, y.v, z.v};
  s.v_robot_in_odom_mps = {x.d1, y.d1, z.d1};
  s.a_robot_in_odom_mps2 = {x.d2, y.d2, z.d2};
  s.roll_rad = roll.v;
  s.pitch_rad = pitch.v;
  s.yaw_rad = yaw.v;
  s.q_odom_robot = Eigen::AngleAxisd(yaw.v, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(pitch.v, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(roll.v, Eigen::Vector3d::UnitX());
  // ZYX Euler rates to body rates.
  const double sr = std::sin(roll.v), cr = std::cos(roll.v);
  const double sp = std::sin(pitch.v), cp = std::cos(pitch.v);
  s.w_robot_radps = {roll.d1 - sp * yaw.d1, cr * pitch.d1 + sr * cp * yaw.d1,
                     -sr * pitch.d1 + cr * cp * yaw.d1};
  // Its time derivative (product rule on the line above, with the Euler angles' second derivatives).
  s.alpha_robot_radps2 = {roll.d2 - cp * pitch.d1 * yaw.d1 - sp * yaw.d2,
                          -sr * roll.d1 * pitch.d1 + cr * pitch.d2 + cr * roll.d1 * cp * yaw.d1 -
                              sr * sp * pitch.d1 * yaw.d1 + sr * cp * yaw.d2,
                          -cr * roll.d1 * pitch.d1 - sr * pitch.d2 - sr * roll.d1 * cp * yaw.d1 -
                              cr * sp * pitch.d1 * yaw.d1 + cr * cp * yaw.d2};
  const Eigen::Vector3d g_in_odom(0.0, 0.0, -gravity_mps2_);
  s.f_robot_mps2 = s.q_odom_robot.conjugate() * (s.a_robot_in_odom_mps2 - g_in_odom);
  return s;
}

}  // namespace deepnav::sim
