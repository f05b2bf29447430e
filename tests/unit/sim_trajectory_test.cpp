#include "tools/sim/trajectory.h"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "sim_test_trajectory.h"
#include "tools/sim/rotation.h"

namespace deepnav::sim {
namespace {

constexpr double kPi = std::numbers::pi;

Trajectory makeTrajectory(const PanelGeometry& panel = {}, const TrajectoryConfig& config = {}) {
  Trajectory t;
  std::string error;
  EXPECT_TRUE(t.init(config, panel, 1000.0, 9.80665, &error)) << error;
  return t;
}

// Rotation vector of q (small angles), for comparing orientations.
Eigen::Vector3d logMap(const Eigen::Quaterniond& q) {
  const Eigen::AngleAxisd aa(q.normalized());
  return aa.angle() * aa.axis();
}

TEST(SimTrajectory, DefaultPlanLastsTwoMinutes) {
  const Trajectory t = makeTrajectory();
  EXPECT_DOUBLE_EQ(t.planDuration_s(), 120.0);
}

TEST(SimTrajectory, VelocityAndAccelerationAreTheDerivativesOfPosition) {
  // GIVEN the default dive WHEN differentiating numerically THEN the analytic derivatives agree everywhere
  test::expectDerivativesOfPosition(makeTrajectory(), 125.0, 0.37, false);
}

TEST(SimTrajectory, AngularRateIsTheDerivativeOfOrientation) {
  const Trajectory t = makeTrajectory();
  const double h = 1e-4;
  for (double time = 0.0; time <= 125.0; time += 0.41) {
    const KinematicState s = t.stateAt(time);
    const Eigen::Quaterniond q0 = t.stateAt(time - h).q_odom_robot, q1 = t.stateAt(time + h).q_odom_robot;
    const Eigen::Vector3d w_numeric = logMap(q0.conjugate() * q1) / (2 * h);
    EXPECT_LT((w_numeric - s.w_robot_radps).norm(), 1e-6) << "t = " << time;
  }
}

TEST(SimTrajectory, SpecificForceIsAccelerationMinusGravityInTheRobotFrame) {
  const Trajectory t = makeTrajectory();
  const KinematicState s = t.stateAt(33.3);
  const Eigen::Vector3d expected =
      s.q_odom_robot.conjugate() * (s.a_robot_in_odom_mps2 + Eigen::Vector3d(0, 0, 9.80665));
  EXPECT_LT((s.f_robot_mps2 - expected).norm(), 1e-12);
  EXPECT_NEAR(s.f_robot_mps2.z(), 9.80665, 0.1);  // nearly level: gravity reaction along +z (FLU)
}

TEST(SimTrajectory, AccelerationIsContinuousAtPhaseJoints) {
  // C2: the acceleration just before and after each joint of the plan agree.
  const Trajectory t = makeTrajectory();
  for (double joint : {4.0, 30.0, 42.0, 69.0, 81.0, 108.0}) {
    const KinematicState before = t.stateAt(joint - 1e-7), after = t.stateAt(joint + 1e-7);
    EXPECT_LT((before.a_robot_in_odom_mps2 - after.a_robot_in_odom_mps2).norm(), 1e-5) << joint;
  }
}

TEST(SimTrajectory, DwellsFaceEachSideAtTheStandoff) {
  // GIVEN a panel rotated and moved in odom, no disturbances
  PanelGeometry panel;
  panel.centre_in_odom_m = {3.0, -2.0};
  panel.front_yaw_deg = 35.0;
  TrajectoryConfig config;
  config.surge_amplitude_m = config.sway_amplitude_m = config.heave_amplitude_m = 0.0;
  config.roll_amplitude_deg = config.pitch_amplitude_deg = config.yaw_amplitude_deg = 0.0;
  const Trajectory t = makeTrajectory(panel, config);
  const Eigen::Vector2d centre(3.0, -2.0);
  // Middle of each dwell: left face (+90 deg), front (0), right (-90 deg).
  const double dwell_mid[3] = {36.0, 75.0, 114.0};
  const double face_deg[3] = {90.0, 0.0, -90.0};
  for (int i = 0; i < 3; ++i) {
    const KinematicState s = t.stateAt(dwell_mid[i]);
    const double normal_yaw = (35.0 + face_deg[i]) * kDegToRad;
    const Eigen::Vector2d normal(std::cos(normal_yaw), std::sin(normal_yaw));
    const Eigen::Vector2d offset = s.p_robot_in_odom_m.head<2>() - centre;
    // THEN the robot is standoff_m from the face, in front of its centre, at the circling depth
    EXPECT_NEAR(offset.dot(normal) - panel.half_width_m, 1.5, 1e-9) << i;
    EXPECT_NEAR(offset.dot(Eigen::Vector2d(-normal.y(), normal.x())), 0.0, 1e-9) << i;
    EXPECT_NEAR(s.p_robot_in_odom_m.z(), 1.5, 1e-9);
    // AND the cameras (robot +x) look straight at the face
    EXPECT_NEAR(wrapToPi(s.yaw_rad - (normal_yaw + kPi)), 0.0, 1e-9) << i;
  }
}

TEST(SimTrajectory, CirclingKeepsClearOfThePanelAndLooksAtIt) {
  const Trajectory t = makeTrajectory();
  const PanelGeometry panel;
  for (double time = 30.0; time <= 120.0; time += 0.25) {
    const KinematicState s = t.stateAt(time);
    const Eigen::Vector2d p = s.p_robot_in_odom_m.head<2>();
    // Distance to the footprint: a square of half width 1 m with corners rounded at 0.15 m.
    const double inner = panel.half_width_m - panel.corner_radius_m;
    const Eigen::Vector2d outside(std::max(std::abs(p.x()) - inner, 0.0), std::max(std::abs(p.y()) - inner, 0.0));
    const double clearance = outside.norm() - panel.corner_radius_m;
    EXPECT_GT(clearance, 1.35) << time;
    EXPECT_LT(clearance, 1.75) << time;
    // The panel centre stays within +-25 deg of the optical axis.
    const Eigen::Vector3d centre_in_robot = s.q_odom_robot.conjugate() * (Eigen::Vector3d(0, 0, 0.75) - s.p_robot_in_odom_m);
    EXPECT_LT(std::abs(std::atan2(centre_in_robot.y(), centre_in_robot.x())), 25.0 * kDegToRad) << time;
  }
}

TEST(SimTrajectory, MotionIsRovLike) {
  const Trajectory t = makeTrajectory();
  double max_speed = 0.0, max_rate = 0.0, max_tilt = 0.0;
  for (double time = 0.0; time <= 120.0; time += 0.05) {
    const KinematicState s = t.stateAt(time);
    max_speed = std::max(max_speed, s.v_robot_in_odom_mps.norm());
    max_rate = std::max(max_rate, s.w_robot_radps.norm());
    max_tilt = std::max({max_tilt, std::abs(s.roll_rad), std::abs(s.pitch_rad)});
  }
  EXPECT_LT(max_speed, 0.8);
  EXPECT_LT(max_rate, 25.0 * kDegToRad);
  EXPECT_LT(max_tilt, 1.6 * kDegToRad);
  EXPECT_GT(max_tilt, 0.5 * kDegToRad);  // the disturbances are there
}

TEST(SimTrajectory, RejectsABadPlan) {
  Trajectory t;
  std::string error;
  TrajectoryConfig config;
  config.start_distance_m = 1.0;  // closer than the standoff
  EXPECT_FALSE(t.init(config, PanelGeometry{}, 1000.0, 9.81, &error));
  EXPECT_NE(error.find("start_distance_m"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::sim
