// Compass, depth and attitude models: the scalar sensors.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_stats.h"
#include "tools/sim/rotation.h"
#include "tools/sim/sensors/attitude_model.h"
#include "tools/sim/sensors/compass_model.h"
#include "tools/sim/sensors/depth_model.h"

namespace deepnav::sim {
namespace {

using test::mean;
using test::restingState;
using test::stddev;
constexpr double kPi = std::numbers::pi;

KinematicState yawed(double yaw_rad) { return test::restingStateYawed(yaw_rad); }

TEST(SimCompassModel, HeadingIsClockwiseFromNorthWithBiasAndDeclination) {
  CompassConfig c;
  c.noise_deg = 0.0;
  c.bias_deg = 2.0;
  c.declination_deg = 5.0;
  CompassModel compass;
  std::string error;
  ASSERT_TRUE(compass.init(c, PanelGeometry{}, 0.0, 1, &error));
  // Facing east (yaw 0): true heading 90 deg; magnetic = 90 - 5; plus 2 deg of bias.
  EXPECT_NEAR(compass.measure(yawed(0.0), 0).heading_rad, 87.0 * kDegToRad, 1e-12);
  // Facing north-west (yaw 135 deg): true heading 315 deg.
  EXPECT_NEAR(compass.measure(yawed(0.75 * kPi), 0).heading_rad, 312.0 * kDegToRad, 1e-12);
  EXPECT_FALSE(compass.measure(yawed(0.0), 0).is_true);
  c.true_north = true;  // a gyrocompass ignores the declination
  ASSERT_TRUE(compass.init(c, PanelGeometry{}, 0.0, 1, &error));
  EXPECT_NEAR(compass.measure(yawed(0.0), 0).heading_rad, 92.0 * kDegToRad, 1e-12);
  EXPECT_TRUE(compass.measure(yawed(0.0), 0).is_true);
}

TEST(SimCompassModel, NoiseStdMatchesAndHeadingWraps) {
  CompassConfig c;
  c.noise_deg = 0.5;
  c.bias_deg = 0.0;
  CompassModel compass;
  std::string error;
  ASSERT_TRUE(compass.init(c, PanelGeometry{}, 0.0, 9, &error));
  const KinematicState north = yawed(kPi / 2.0);  // heading 0: noise wraps around 2 pi
  std::vector<double> err;
  for (int k = 0; k < 20000; ++k) {
    const HeadingSample h = compass.measure(north, k);
    ASSERT_GE(h.heading_rad, 0.0);
    ASSERT_LT(h.heading_rad, 2.0 * kPi);
    err.push_back(wrapToPi(h.heading_rad));
  }
  EXPECT_NEAR(stddev(err) / (0.5 * kDegToRad), 1.0, 0.05);
  EXPECT_NEAR(compass.measure(north, 0).sigma_rad, 0.5 * kDegToRad, 1e-15);
}

TEST(SimDepthModel, PressureFollowsHydrostaticsAndNoiseStdMatches) {
  EnvironmentConfig env;  // origin and seabed at 1000 m
  DepthConfig c;
  c.noise_m = 0.02;
  c.p_sensor_in_robot_m = {0.0, 0.0, 0.5};  // port 0.5 m above the robot origin
  DepthModel depth;
  std::string error;
  ASSERT_TRUE(depth.init(c, env, 4, &error));
  const KinematicState s = restingState(1.5);  // robot at 998.5 m, sensor at 998.0 m
  EXPECT_NEAR(depth.trueDepth_m(s), 998.0, 1e-9);
  std::vector<double> depth_err, pressure_err;
  const double rho_g = 1028.0 * 9.80665;
  for (int k = 0; k < 20000; ++k) {
    const DepthSample m = depth.measure(s, k);
    pressure_err.push_back(m.pressure_pa - (101325.0 + rho_g * 998.0));
    depth_err.push_back(m.depth_m - 998.0);
    ASSERT_NEAR(m.depth_m, (m.pressure_pa - 101325.0) / rho_g, 1e-9);
  }
  EXPECT_NEAR(stddev(depth_err) / 0.02, 1.0, 0.05);
  EXPECT_NEAR(stddev(pressure_err) / (0.02 * rho_g), 1.0, 0.05);
  EXPECT_NEAR(mean(depth_err), 0.0, 0.001);
}

TEST(SimAttitudeModel, RollAndPitchNoiseStdMatches) {
  AttitudeConfig c;
  c.noise_deg = 0.1;
  AttitudeModel attitude;
  std::string error;
  ASSERT_TRUE(attitude.init(c, 11, &error));
  KinematicState s = restingState();
  s.roll_rad = 0.02;
  s.pitch_rad = -0.03;
  std::vector<double> roll_err, pitch_err;
  for (int k = 0; k < 20000; ++k) {
    const AttitudeSample m = attitude.measure(s, k);
    roll_err.push_back(m.roll_rad - 0.02);
    pitch_err.push_back(m.pitch_rad + 0.03);
  }
  EXPECT_NEAR(stddev(roll_err) / (0.1 * kDegToRad), 1.0, 0.05);
  EXPECT_NEAR(stddev(pitch_err) / (0.1 * kDegToRad), 1.0, 0.05);
  EXPECT_NEAR(mean(roll_err), 0.0, 1e-5);
}

}  // namespace
}  // namespace deepnav::sim
