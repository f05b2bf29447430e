#include "tools/sim/sensors/dvl_model.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_dvl.h"
#include "sim_test_stats.h"
#include "tools/sim/rotation.h"

namespace deepnav::sim {
namespace {

using test::makeDvl;
using test::noiselessDvlConfig;
using test::restingState;
using test::stddev;

constexpr std::uint64_t kDvlSeed = 3;

TEST(SimDvlModel, NoiseIsHalfAPercentOfSpeedPlusOneMillimetre) {
  DvlModel dvl = makeDvl(DvlConfig{}, kDvlSeed);
  KinematicState s = restingState(1.5);
  s.v_robot_in_odom_mps = {0.3, -0.4, 0.0};  // 0.5 m/s
  const double sigma = 0.005 * 0.5 + 0.001;
  EXPECT_DOUBLE_EQ(dvl.sigmaAtSpeed_mps(0.5), sigma);
  const Eigen::Vector3d v_true = dvl.trueVelocity_mps(s);
  std::vector<double> err[3];
  for (int k = 0; k < 20000; ++k) {
    const DvlSample m = dvl.measure(s, TimeUs{k} * 200000);
    ASSERT_TRUE(m.valid);
    EXPECT_DOUBLE_EQ(m.fom_mps, sigma);
    for (int i = 0; i < 3; ++i) err[i].push_back(m.v_dvl_mps[i] - v_true[i]);
  }
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(stddev(err[i]) / sigma, 1.0, 0.05) << "axis " << i;
}

TEST(SimDvlModel, MeasuresTheLeverArmPointInTheMountedFrame) {
  DvlConfig c = noiselessDvlConfig();
  c.p_dvl_in_robot_m = {1.0, 0.0, -0.5};
  c.mount_rpy_deg = {0.0, 0.0, 45.0};
  DvlModel dvl = makeDvl(c, kDvlSeed);
  KinematicState s = restingState(3.0);
  s.v_robot_in_odom_mps = {0.2, 0.0, 0.0};
  s.w_robot_radps = {0.0, 0.0, 0.5};  // yawing: the DVL point at +1 m x moves +0.5 m/s along y
  const DvlSample m = dvl.measure(s, 0);
  ASSERT_TRUE(m.valid);
  const Eigen::Vector3d v_point_in_robot(0.2, 0.5, 0.0);
  const Eigen::Vector3d expected = rotationFromRpyDeg({0.0, 0.0, 45.0}).transpose() * v_point_in_robot;
  EXPECT_LT((m.v_dvl_mps - expected).norm(), 1e-12);
}

TEST(SimDvlModel, JanusBeamsRangeToAFlatSeabed) {
  DvlModel dvl = makeDvl(noiselessDvlConfig(), kDvlSeed);
  const DvlSample level = dvl.measure(restingState(2.0), 0);
  EXPECT_EQ(level.beam_valid_mask, 0xF);
  for (double r : level.beam_range_m) EXPECT_NEAR(r, 2.0 / std::cos(30.0 * kDegToRad), 1e-12);
  EXPECT_NEAR(level.altitude_m, 2.0, 1e-12);
  // Pitched nose-down by 10 deg (FLU: +pitch): the forward beams shorten, the aft ones lengthen.
  KinematicState pitched = restingState(2.0);
  pitched.q_odom_robot = Eigen::AngleAxisd(10.0 * kDegToRad, Eigen::Vector3d::UnitY());
  const DvlSample m = dvl.measure(pitched, 0);
  for (int i = 0; i < 4; ++i) {
    const Eigen::Vector3d beam_in_odom = pitched.q_odom_robot * dvl.beamInDvl(i);
    EXPECT_NEAR(m.beam_range_m[i], 2.0 / -beam_in_odom.z(), 1e-12) << i;
  }
  EXPECT_LT(m.beam_range_m[0], level.beam_range_m[0]);  // beam 0 at azimuth 45 deg: forward-left
  EXPECT_GT(m.beam_range_m[2], level.beam_range_m[2]);
}

TEST(SimDvlModel, DropsOutOutsideTheAltitudeWindow) {
  DvlConfig c = noiselessDvlConfig();
  c.min_altitude_m = 0.5;
  c.max_altitude_m = 30.0;
  DvlModel dvl = makeDvl(c, kDvlSeed);
  KinematicState s = restingState();
  s.v_robot_in_odom_mps = {0.1, 0.0, 0.0};
  for (double altitude : {0.4, 30.5, 100.0, -1.0}) {
    s.p_robot_in_odom_m.z() = altitude;
    const DvlSample m = dvl.measure(s, 0);
    EXPECT_FALSE(m.valid) << altitude;
    EXPECT_EQ(m.beam_valid_mask, 0) << altitude;
    EXPECT_EQ(m.v_dvl_mps, Eigen::Vector3d::Zero());
  }
  for (double altitude : {0.6, 29.5}) {
    s.p_robot_in_odom_m.z() = altitude;
    EXPECT_TRUE(dvl.measure(s, 0).valid) << altitude;
  }
}

TEST(SimDvlModel, NeedsThreeBeams) {
  // Rolled 40 deg near the top of the window: the beams on the low side exceed max range.
  DvlConfig c = noiselessDvlConfig();
  c.max_altitude_m = 10.0;
  DvlModel dvl = makeDvl(c, kDvlSeed);
  KinematicState s = restingState(9.0);
  s.q_odom_robot = Eigen::AngleAxisd(40.0 * kDegToRad, Eigen::Vector3d::UnitX());
  const DvlSample m = dvl.measure(s, 0);
  EXPECT_NE(m.beam_valid_mask, 0xF);
  EXPECT_FALSE(m.valid);
}

}  // namespace
}  // namespace deepnav::sim
