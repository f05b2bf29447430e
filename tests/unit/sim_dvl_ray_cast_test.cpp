// dvl.ray_cast: the beams meet the renderer's scene (render/scene.h). A beam aimed at a panel face gets
// the face's (short) range; a range jump or a range outside the window costs the lock; a fish in a beam
// gives that beam the fish's Doppler, an outlier.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "sim_test_stats.h"
#include "tools/sim/render/fish_school.h"
#include "tools/sim/sensors/dvl_beam_solver.h"
#include "tools/sim/sensors/dvl_model.h"
#include "tools/sim/scenario.h"

namespace deepnav::sim {
namespace {

using test::restingState;

constexpr std::uint64_t kSceneSeed = 4;

DvlConfig rayCastBeams() {
  DvlConfig c;
  c.noise_fraction_of_speed = 0.0;
  c.noise_floor_mps = 0.0;
  c.range_noise_m = 0.0;
  c.p_dvl_in_robot_m = {0.0, 0.0, 0.0};
  c.ray_cast = true;
  return c;
}

DvlModel makeDvl(const Scenario& scenario, const DvlConfig& c) {
  DvlModel dvl;
  std::string error;
  EXPECT_TRUE(dvl.init(c, scenario.environment.seabedZInOdom_m(), 9, &error)) << error;
  EXPECT_TRUE(dvl.attachScene(scenario, kSceneSeed, &error)) << error;
  return dvl;
}

// Level, facing east, 1.2 m above the seabed, 0.4 m outside the plain face (y = -1 m, the panel frame is
// the odometry frame with the default scenario). Beams 0 and 1 (azimuths 45 and 135 deg) lean 0.354 m
// towards +y per metre of range: they meet the face after 0.4 / 0.354 = 1.131 m, at 0.22 m above the
// seabed, where the seabed alone would be 1.2 / cos 30 = 1.386 m (+-0.07 m of relief) away.
KinematicState besideThePlainFace(double y_m = -1.4) {
  KinematicState s = restingState(1.2);
  s.p_robot_in_odom_m.y() = y_m;
  return s;
}

constexpr double kFaceRange_m = 0.4 / (0.5 * M_SQRT1_2);

TEST(SimDvlRayCast, BeamsAimedAtAPanelFaceGetTheShortRange) {
  const Scenario scenario;
  DvlModel dvl = makeDvl(scenario, rayCastBeams());
  const DvlSample m = dvl.measure(besideThePlainFace(), 0);
  ASSERT_TRUE(m.valid);
  EXPECT_EQ(m.beam_valid_mask, 0xF);
  EXPECT_NEAR(m.beam_range_m[0], kFaceRange_m, 1e-4);  // float ray test
  EXPECT_NEAR(m.beam_range_m[1], kFaceRange_m, 1e-4);
  for (int i : {2, 3}) EXPECT_NEAR(m.beam_range_m[i], 1.2 / std::cos(M_PI / 6.0), 0.07) << i;
  // The altitude comes out short, the velocity stays right (the panel does not move).
  EXPECT_LT(m.altitude_m, 1.12);
  EXPECT_LT(m.v_dvl_mps.norm(), 1e-9);
}

TEST(SimDvlRayCast, ARangeJumpCostsTheLockForOnePing) {
  const Scenario scenario;
  DvlConfig c = rayCastBeams();
  c.lock_range_jump_fraction = 0.1;
  DvlModel dvl = makeDvl(scenario, c);
  EXPECT_EQ(dvl.measure(besideThePlainFace(-3.0), 0).beam_valid_mask, 0xF);  // seabed only
  const DvlSample jumped = dvl.measure(besideThePlainFace(), 200000);  // onto the face: -18 %
  EXPECT_EQ(jumped.beam_valid_mask, 0b1100);
  EXPECT_FALSE(jumped.valid);
  const DvlSample tracking = dvl.measure(besideThePlainFace(), 400000);  // the face tracked now
  EXPECT_EQ(tracking.beam_valid_mask, 0xF);
  EXPECT_NEAR(tracking.beam_range_m[0], kFaceRange_m, 1e-4);
}

TEST(SimDvlRayCast, AFaceRangeBelowTheWindowLosesTheLock) {
  const Scenario scenario;
  DvlConfig c = rayCastBeams();
  c.min_altitude_m = 1.0;  // the face beams' vertical range is 1.131 cos 30 = 0.98 m
  DvlModel dvl = makeDvl(scenario, c);
  const DvlSample m = dvl.measure(besideThePlainFace(), 0);
  EXPECT_EQ(m.beam_valid_mask, 0b1100);
  EXPECT_FALSE(m.valid);
}

// Beam 0 aimed through a fish 0.6 m away: the beam ranges on the fish and measures b . (v_dvl - v_fish);
// the DVL is at rest, so the solution is (B^T B)^-1 b_0 (-b_0 . v_fish) instead of zero.
TEST(SimDvlRayCast, AFishInABeamGivesAnOutlier) {
  Scenario scenario;
  scenario.water.fish_count = 3;
  FishSchool school;
  school.init(3, scenario.panel.half_width_m, scenario.trajectory.standoff_m, kSceneSeed);
  DvlModel dvl = makeDvl(scenario, rayCastBeams());
  const Eigen::Vector3d b0 = dvl.beamInDvl(0);  // level, facing east: DVL frame = odometry axes
  // The fish whose velocity along beam 0 is largest.
  double best_radial = 0.0;
  Eigen::Vector3d fish_p = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    Eigen::Matrix3f R;
    Eigen::Vector3f p, before, after;
    school.poseAt(i, 0.0, &R, &p);
    school.poseAt(i, -0.01, &R, &before);
    school.poseAt(i, 0.01, &R, &after);
    const Eigen::Vector3d v = (after - before).cast<double>() / 0.02;
    if (std::abs(b0.dot(v)) > std::abs(best_radial)) best_radial = b0.dot(v), fish_p = p.cast<double>();
  }
  ASSERT_GT(std::abs(best_radial), 0.01);
  KinematicState s = restingState();
  s.p_robot_in_odom_m = fish_p - 0.6 * b0;
  const DvlSample m = dvl.measure(s, 0);
  ASSERT_TRUE(m.beam_valid_mask & 1);
  EXPECT_LT(m.beam_range_m[0], 0.6);
  EXPECT_GT(m.beam_range_m[0], 0.45);  // fish are 5-14 cm long
  std::array<Eigen::Vector3d, kDvlBeams> beams;
  std::array<double, kDvlBeams> u{}, sigma{};
  for (int i = 0; i < kDvlBeams; ++i) beams[i] = dvl.beamInDvl(i);
  u[0] = -best_radial;
  Eigen::Vector3d expected;
  Eigen::Matrix3d cov;
  ASSERT_TRUE(solveDvlBeams(beams, u, sigma, m.beam_valid_mask, &expected, &cov));
  EXPECT_LT((m.v_dvl_mps - expected).norm(), 1e-6);
  EXPECT_GT(m.v_dvl_mps.norm(), 0.01);
}

}  // namespace
}  // namespace deepnav::sim
