#include "tools/sim/trajectory_plan.h"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "tools/sim/rotation.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/trajectory.h"
#include "sim_test_trajectory.h"

namespace deepnav::sim {
namespace {

constexpr double kPi = std::numbers::pi;

// Approach the left face from 8 m while descending, go to the front, hold closer, face the right face.
TrajectoryConfig scriptedDive() {
  TrajectoryConfig c;
  c.surge_amplitude_m = c.sway_amplitude_m = c.heave_amplitude_m = 0.0;
  c.roll_amplitude_deg = c.pitch_amplitude_deg = c.yaw_amplitude_deg = 0.0;
  c.plan = {{90.0, 8.0, 994.0, 0.75, 0.0, 4.0},
            {90.0, 1.5, 998.5, 0.75, 30.0, 10.0},
            {0.0, 1.5, 998.5, 0.75, 20.0, 5.0},
            {0.0, 1.1, 998.6, 1.0, 8.0, 30.0},
            {-90.0, 1.5, 998.5, 0.75, 40.0, 10.0}};
  return c;
}

Trajectory makeTrajectory(const TrajectoryConfig& config) {
  Trajectory t;
  std::string error;
  EXPECT_TRUE(t.init(config, PanelGeometry{}, 1000.0, 9.80665, &error)) << error;
  return t;
}

TEST(SimTrajectoryPlan, LastsItsHoldsAndMoves) {
  EXPECT_DOUBLE_EQ(makeTrajectory(scriptedDive()).planDuration_s(), 4 + 40 + 25 + 38 + 50);
}

TEST(SimTrajectoryPlan, HoldsEachWaypointAtItsStandoffDepthAndBearing) {
  // GIVEN the scripted dive without disturbances WHEN in the middle of each hold THEN the robot is at the
  // waypoint: on the face normal at half width + standoff (face centres: the superellipse's radius there
  // is exactly a), at its depth, looking at the face (yaw = bearing + 180 deg there, where the normal
  // offset is zero).
  const TrajectoryConfig c = scriptedDive();
  const Trajectory t = makeTrajectory(c);
  double t_s = 0.0;
  for (std::size_t i = 0; i < c.plan.size(); ++i) {
    t_s += c.plan[i].move_s;
    const KinematicState s = t.stateAt(t_s + 0.5 * c.plan[i].hold_s);
    const double bearing = c.plan[i].bearing_deg * kDegToRad;
    const double a = 1.0 + c.plan[i].standoff_m;
    EXPECT_NEAR(s.p_robot_in_odom_m.x(), a * std::cos(bearing), 1e-9) << "waypoint " << i;
    EXPECT_NEAR(s.p_robot_in_odom_m.y(), a * std::sin(bearing), 1e-9) << "waypoint " << i;
    EXPECT_NEAR(s.p_robot_in_odom_m.z(), 1000.0 - c.plan[i].depth_m, 1e-9) << "waypoint " << i;
    EXPECT_NEAR(wrapToPi(s.yaw_rad - bearing - kPi), 0.0, 1e-9) << "waypoint " << i;
    EXPECT_LT(s.v_robot_in_odom_mps.norm(), 1e-12) << "at rest during the hold, waypoint " << i;
    t_s += c.plan[i].hold_s;
  }
}

TEST(SimTrajectoryPlan, VelocityAndAccelerationAreTheDerivativesOfPosition) {
  // Central differences (h = 1e-4 s): the analytic derivatives agree through every move and joint.
  test::expectDerivativesOfPosition(makeTrajectory(scriptedDive()), 160.0, 0.29, true);
}

TEST(SimTrajectoryPlan, StaysClearOfThePanelWhileGoingAround) {
  // The robot origin keeps at least the smallest standoff from the footprint (a square of half width 1):
  // the superellipse passes ~0.1 m outside the corners' standoff.
  const Trajectory t = makeTrajectory(scriptedDive());
  for (double time = 0.0; time <= 160.0; time += 0.1) {
    const Eigen::Vector3d p = t.stateAt(time).p_robot_in_odom_m;
    const double dx = std::max(0.0, std::abs(p.x()) - 1.0), dy = std::max(0.0, std::abs(p.y()) - 1.0);
    EXPECT_GT(std::hypot(dx, dy), 1.1 - 1e-9) << "t = " << time;
  }
}

TEST(SimTrajectoryPlan, ScenarioWaypointsInheritAbsentValuesAndNeedAMove) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario("trajectory:\n  plan:\n"
                            "    - {bearing_deg: 90, standoff_m: 6, depth_m: 995, hold_s: 3}\n"
                            "    - {standoff_m: 1.5, depth_m: 998.5, move_s: 20}\n"
                            "    - {bearing_deg: 0, move_s: 15, hold_s: 9}\n",
                            "plan.yaml", &s, &error))
      << error;
  ASSERT_EQ(s.trajectory.plan.size(), 3u);
  EXPECT_EQ(s.trajectory.plan[1].bearing_deg, 90.0);
  EXPECT_EQ(s.trajectory.plan[1].hold_s, 0.0) << "times are not inherited";
  EXPECT_EQ(s.trajectory.plan[2].standoff_m, 1.5);
  EXPECT_EQ(s.trajectory.plan[2].depth_m, 998.5);

  EXPECT_FALSE(parseScenario("trajectory:\n  plan:\n    - {bearing_deg: 90}\n    - {bearing_deg: 0}\n",
                             "plan.yaml", &s, &error));
  EXPECT_NE(error.find("trajectory.plan[1].move_s"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("trajectory:\n  plan:\n    - {depth_m: 1000.5}\n", "plan.yaml", &s, &error));
  EXPECT_NE(error.find("trajectory.plan[0].depth_m"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("trajectory:\n  plan:\n    - {bearing: 90}\n", "plan.yaml", &s, &error));
  EXPECT_NE(error.find("bearing"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::sim
