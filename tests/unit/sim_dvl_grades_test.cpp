// dvl.grade: the loader sets the grade's datasheet figures first, then the explicit keys override them;
// each grade runs the default dive.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensor_simulator.h"

namespace deepnav::sim {
namespace {

Scenario parse(const std::string& yaml) {
  Scenario s;
  std::string error;
  EXPECT_TRUE(parseScenario(yaml, "grade.yaml", &s, &error)) << error;
  return s;
}

std::string parseError(const std::string& yaml) {
  Scenario s;
  std::string error;
  EXPECT_FALSE(parseScenario(yaml, "grade.yaml", &s, &error));
  return error;
}

TEST(SimDvlGrades, GradeSetsItsDatasheetFigures) {
  const DvlConfig c = parse("dvl: {grade: standard}").dvl;
  const DvlGradeSpec& g = dvlGradeSpec(DvlGrade::kStandard);
  EXPECT_EQ(c.grade, DvlGrade::kStandard);
  EXPECT_EQ(c.scale_factor_sigma_percent, g.long_term_percent);
  EXPECT_EQ(c.bias_sigma_mps, g.long_term_constant_mps);
  EXPECT_EQ(c.min_altitude_m, g.min_altitude_m);
  EXPECT_EQ(c.max_altitude_m, g.max_altitude_m);
  EXPECT_EQ(c.max_ping_rate_hz, g.max_ping_rate_hz);
  EXPECT_EQ(c.rate_hz, g.max_ping_rate_hz);
  EXPECT_EQ(c.noise_fraction_of_speed, 0.0);
  EXPECT_EQ(c.noise_floor_mps, 0.0);
  // Horizontal per-ping sigma = beam sigma / (sqrt(2) sin 30 deg) for a 4-beam Janus.
  EXPECT_NEAR(c.beam_noise_floor_mps / (std::sqrt(2.0) * 0.5), g.ping_sigma_horizontal_mps, 1e-15);
  EXPECT_TRUE(c.usesBeamModel());
  // The rest keeps its defaults.
  EXPECT_EQ(c.p_dvl_in_robot_m, DvlConfig{}.p_dvl_in_robot_m);
  EXPECT_FALSE(c.ray_cast);
}

TEST(SimDvlGrades, ExplicitKeysOverrideTheGradeWhereverTheyAre) {
  const DvlConfig before = parse("dvl: {max_altitude_m: 20.0, grade: precision, beam_noise_floor_mps: 0.001}").dvl;
  const DvlConfig after = parse("dvl: {grade: precision, max_altitude_m: 20.0, beam_noise_floor_mps: 0.001}").dvl;
  EXPECT_EQ(before, after);
  EXPECT_EQ(before.max_altitude_m, 20.0);
  EXPECT_EQ(before.beam_noise_floor_mps, 0.001);
  EXPECT_EQ(before.min_altitude_m, dvlGradeSpec(DvlGrade::kPrecision).min_altitude_m);
  EXPECT_EQ(parse("dvl: {grade: none}"), parse(""));
}

TEST(SimDvlGrades, BadGradesAndNewKeysAreNamed) {
  EXPECT_NE(parseError("dvl: {grade: navy}").find("key 'dvl.grade' = navy is not one of: none, compact, standard, precision"),
            std::string::npos);
  EXPECT_NE(parseError("dvl: {outlier_probability: 2}").find("dvl.outlier_probability"), std::string::npos);
  EXPECT_NE(parseError("dvl: {misalignment_rpy_deg: [0, 0, 45]}").find("dvl.misalignment_rpy_deg"), std::string::npos);
  EXPECT_NE(parseError("dvl: {max_ping_rate_hz: -1}").find("dvl.max_ping_rate_hz"), std::string::npos);
}

// At the dive's 1.2-1.7 m the echo returns within ~35 ms, sooner than each grade's maximum ping rate
// allows, so every channel tick pings: 120 s at the maximum rate, every ensemble valid.
TEST(SimDvlGrades, EachGradeRunsTheDefaultDiveAtItsMaximumPingRate) {
  for (const char* grade : {"compact", "standard", "precision"}) {
    Scenario scenario = parse(std::string("dvl: {grade: ") + grade + "}");
    SensorSimulator sim;
    std::string error;
    ASSERT_TRUE(sim.init(scenario, 3, &error)) << error;
    SimEvent e;
    int invalid = 0;
    while (sim.next(&e))
      if (e.stream == SimStream::kDvl && !std::get<DvlSample>(e.sample).valid) ++invalid;
    EXPECT_EQ(invalid, 0) << grade;
    EXPECT_EQ(sim.emitted(SimStream::kDvl), static_cast<std::uint64_t>(std::floor(120.0 * scenario.dvl.rate_hz)) + 1)
        << grade;
    EXPECT_EQ(sim.notPinged(SimStream::kDvl), 0u) << grade;
  }
}

}  // namespace
}  // namespace deepnav::sim
