// AHRS roll/pitch errors: fixed biases recovered from the stream, per-dive biases drawn with the
// configured sigma, the noise sequence unchanged by them; the attitude grades in the loader.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_stats.h"
#include "tools/sim/rotation.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensors/attitude_model.h"

namespace deepnav::sim {
namespace {

using test::mean;
using test::restingState;
using test::stddev;

TEST(SimAttitudeBias, FixedBiasesAreRecoveredAndTheNoiseIsUnchanged) {
  AttitudeConfig c;  // noise 0.1 deg
  c.roll_bias_deg = 0.3;
  c.pitch_bias_deg = -0.2;
  AttitudeModel biased, plain;
  std::string error;
  ASSERT_TRUE(biased.init(c, 11, &error));
  ASSERT_TRUE(plain.init(AttitudeConfig{}, 11, &error));
  KinematicState s = restingState();
  s.roll_rad = 0.02;
  s.pitch_rad = -0.03;
  std::vector<double> roll_err_deg, pitch_err_deg;
  for (int k = 0; k < 20000; ++k) {
    const AttitudeSample b = biased.measure(s, k), p = plain.measure(s, k);
    roll_err_deg.push_back((b.roll_rad - 0.02) / kDegToRad);
    pitch_err_deg.push_back((b.pitch_rad + 0.03) / kDegToRad);
    ASSERT_NEAR(b.roll_rad - p.roll_rad, 0.3 * kDegToRad, 1e-15);
    ASSERT_NEAR(b.pitch_rad - p.pitch_rad, -0.2 * kDegToRad, 1e-15);
  }
  // sd of the mean: 0.1 deg / sqrt(20000) = 0.0007 deg; 0.003 deg is > 4 sigma.
  EXPECT_NEAR(mean(roll_err_deg), 0.3, 0.003);
  EXPECT_NEAR(mean(pitch_err_deg), -0.2, 0.003);
  EXPECT_NEAR(stddev(roll_err_deg) / 0.1, 1.0, 0.05);
  std::printf("[attitude] bias configured 0.3 / -0.2 deg, recovered %.4f / %.4f deg\n", mean(roll_err_deg),
              mean(pitch_err_deg));
}

TEST(SimAttitudeBias, PerDiveBiasHasTheConfiguredSigma) {
  AttitudeConfig c;
  c.bias_sigma_deg = 0.2;
  std::vector<double> roll_deg, pitch_deg;
  std::string error;
  for (std::uint64_t seed = 1; seed <= 4000; ++seed) {
    AttitudeModel m;
    ASSERT_TRUE(m.init(c, seed, &error));
    roll_deg.push_back(m.rollBias_rad() / kDegToRad);
    pitch_deg.push_back(m.pitchBias_rad() / kDegToRad);
  }
  // 4000 dives: sd of the mean 0.2 / sqrt(4000) = 0.003 deg; of the sd 0.2 / sqrt(8000) = 0.0022 deg.
  EXPECT_NEAR(mean(roll_deg), 0.0, 0.013);
  EXPECT_NEAR(mean(pitch_deg), 0.0, 0.013);
  EXPECT_NEAR(stddev(roll_deg), 0.2, 0.01);
  EXPECT_NEAR(stddev(pitch_deg), 0.2, 0.01);
}

TEST(SimAttitudeGrades, GradeSetsItsFiguresAndExplicitKeysOverride) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario("attitude: {grade: ahrs_mems}\n", "t.yaml", &s, &error)) << error;
  EXPECT_EQ(s.attitude.grade, AttitudeGrade::kAhrsMems);
  EXPECT_EQ(s.attitude.bias_sigma_deg, 0.2);
  ASSERT_TRUE(parseScenario("attitude: {bias_sigma_deg: 0.05, grade: gyrocompass}\n", "t.yaml", &s, &error));
  EXPECT_EQ(s.attitude.bias_sigma_deg, 0.05);
  EXPECT_EQ(s.attitude.noise_deg, 0.01);
  EXPECT_FALSE(parseScenario("attitude: {roll_bias_deg: 100}\n", "t.yaml", &s, &error));
  EXPECT_NE(error.find("attitude.roll_bias_deg"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::sim
