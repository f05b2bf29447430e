#include "tools/sim/scenario_loader.h"
#include "tests/support/source_paths.h"
#include "vision/calib/flat_port.h"

#include <sstream>
#include <string>

#include <gtest/gtest.h>

namespace deepnav::sim {
namespace {

const std::string kScenarioDir = deepnav::testing::sourceDir() + "/tools/sim/scenarios/";

std::string parseError(const std::string& yaml) {
  Scenario s;
  std::string error;
  EXPECT_FALSE(parseScenario(yaml, "test.yaml", &s, &error)) << yaml;
  return error;
}

TEST(SimScenarioLoader, DefaultFileSpellsOutTheBuiltInDefaults) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(loadScenario(kScenarioDir + "default.yaml", &s, &error)) << error;
  Scenario expected;
  expected.description = s.description;
  EXPECT_FALSE(s.description.empty());
  EXPECT_TRUE(s == expected) << "default.yaml and the struct defaults disagree";
  EXPECT_EQ(s.water.preset, WaterPreset::kModerate);
}

TEST(SimScenarioLoader, VariantsLoad) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(loadScenario(kScenarioDir + "clear.yaml", &s, &error)) << error;
  EXPECT_EQ(s.water.preset, WaterPreset::kClear);
  EXPECT_EQ(s.name, "clear");
  ASSERT_TRUE(loadScenario(kScenarioDir + "murky.yaml", &s, &error)) << error;
  EXPECT_EQ(s.water.preset, WaterPreset::kMurky);
  ASSERT_TRUE(loadScenario(kScenarioDir + "no-markers.yaml", &s, &error)) << error;
  EXPECT_FALSE(s.panel.markers_enabled);
  EXPECT_EQ(s.imu, ImuConfig{});
}

TEST(SimScenarioLoader, EmptyFileGivesDefaultsNamedAfterTheFile) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario("", "dir/quiet-dive.yaml", &s, &error)) << error;
  EXPECT_EQ(s.name, "quiet-dive");
  EXPECT_DOUBLE_EQ(s.duration_s, 120.0);
}

TEST(SimScenarioLoader, ReadsNestedValuesAndFaults) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario(R"(
duration_s: 30
dvl: {rate_hz: 8, p_dvl_in_robot_m: [0.1, 0.2, -0.3]}
panel: {centre_in_odom_m: [5, -4], front_yaw_deg: 30}
faults:
  - {stream: dvl, kind: dropout, t_start_s: 10, t_end_s: 12}
  - {stream: imu, kind: time_jitter, t_start_s: 1, t_end_s: 2, params: {std_ms: 3}}
  - {stream: compass, kind: outlier, t_start_s: 5, t_end_s: 6, params: {magnitude_sigma: 20, probability: 0.5}}
)", "test.yaml", &s, &error)) << error;
  EXPECT_DOUBLE_EQ(s.duration_s, 30.0);
  EXPECT_DOUBLE_EQ(s.dvl.rate_hz, 8.0);
  EXPECT_DOUBLE_EQ(s.dvl.p_dvl_in_robot_m[2], -0.3);
  EXPECT_DOUBLE_EQ(s.panel.centre_in_odom_m[1], -4.0);
  ASSERT_EQ(s.faults.size(), 3u);
  EXPECT_EQ(s.faults[0].stream, SimStream::kDvl);
  EXPECT_EQ(s.faults[0].kind, FaultKind::kDropout);
  EXPECT_EQ(s.faults[1].stream, SimStream::kImu);
  EXPECT_EQ(s.faults[1].kind, FaultKind::kTimeJitter);
  EXPECT_DOUBLE_EQ(s.faults[1].std_ms, 3.0);
  EXPECT_EQ(s.faults[2].stream, SimStream::kCompass);
  EXPECT_DOUBLE_EQ(s.faults[2].magnitude_sigma, 20.0);
  EXPECT_DOUBLE_EQ(s.faults[2].probability, 0.5);
}

TEST(SimScenarioLoader, RejectsAnUnknownKeyByNameAndListsTheAllowedOnes) {
  const std::string error = parseError("imu:\n  rate_hz: 100\n  gyro_nosie: 1\n");
  EXPECT_NE(error.find("test.yaml: unknown key 'imu.gyro_nosie' (line 3)"), std::string::npos) << error;
  EXPECT_NE(error.find("allowed keys: grade, enabled, rate_hz, gyro_noise_deg_per_sqrt_h"), std::string::npos) << error;
  EXPECT_NE(parseError("camra: {}\n").find("unknown key 'camra'"), std::string::npos);
}

TEST(SimScenarioLoader, RejectsOutOfRangeWithKeyAndRange) {
  EXPECT_EQ(parseError("imu: {rate_hz: 5000}"), "test.yaml: key 'imu.rate_hz' = 5000 is out of range [1, 2000] Hz");
  EXPECT_EQ(parseError("dvl: {p_dvl_in_robot_m: [0, 0, 40]}"),
            "test.yaml: key 'dvl.p_dvl_in_robot_m[2]' = 40 is out of range [-10, 10] m");
  EXPECT_EQ(parseError("trajectory: {face_alignment: -0.5}"),
            "test.yaml: key 'trajectory.face_alignment' = -0.5 is out of range [0, 1] (fraction)");
  EXPECT_EQ(parseError("faults: [{stream: imu, kind: time_jitter, t_start_s: 1, t_end_s: 2, params: {std_ms: 5000}}]"),
            "test.yaml: key 'faults[0].params.std_ms' = 5000 is out of range [0, 1000] ms");
}

TEST(SimScenarioLoader, CameraPortRangesAreThePortsDeclaredOnes) {
  // The flat port's keys take the ranges the port declares (flatPortParams(), the board's camera.port.*)
  for (const ParamDecl<FlatPort>& d : flatPortParams()) {
    if (std::string(d.key) == "n_air") continue;  // the scenario's housing is always air
    const std::string unit = std::string(d.unit) == "-" ? "" : d.unit;
    std::ostringstream range;
    range << "[" << d.min << ", " << d.max << "] " << unit;
    EXPECT_NE(parseError("camera: {port: {" + std::string(d.key) + ": 7}}").find(range.str()), std::string::npos)
        << d.key;
  }
  EXPECT_EQ(parseError("camera: {port: {n_glass: 3.5}}"),
            "test.yaml: key 'camera.port.n_glass' = 3.5 is out of range [1, 3] ");
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario("camera: {port: {model: flat, glass_thickness_m: 0.2, n_water: 1.2}}", "test.yaml", &s,
                            &error))
      << error;
  EXPECT_EQ(s.camera.port.glass_thickness_m, 0.2);
  EXPECT_EQ(s.camera.port.n_water, 1.2);
}

TEST(SimScenarioLoader, RejectsWrongTypesAndChoices) {
  EXPECT_NE(parseError("dvl: {rate_hz: fast}").find("key 'dvl.rate_hz' must be a number in Hz"), std::string::npos);
  EXPECT_NE(parseError("camera: {width_px: 688.5}").find("key 'camera.width_px' must be an integer"),
            std::string::npos);
  EXPECT_NE(parseError("imu: {mount_rpy_deg: [0, 0]}").find("'imu.mount_rpy_deg' must be a list of 3 numbers"),
            std::string::npos);
  EXPECT_NE(parseError("water: {preset: soupy}").find("key 'water.preset' = soupy is not one of: clear, moderate, murky"),
            std::string::npos);
  EXPECT_NE(parseError("imu: 3").find("key 'imu' must be a map"), std::string::npos);
  EXPECT_NE(parseError("imu: {enabled: maybe}").find("'imu.enabled' must be true or false"), std::string::npos);
  EXPECT_NE(parseError("imu: [").find("test.yaml: YAML syntax error"), std::string::npos);
}

TEST(SimScenarioLoader, RejectsBadFaults) {
  EXPECT_NE(parseError("faults: [{stream: sonar, kind: dropout, t_start_s: 1, t_end_s: 2}]")
                .find("'faults[0].stream' = sonar is not one of: imu, dvl, compass, attitude, depth, camera"),
            std::string::npos);
  EXPECT_NE(parseError("faults: [{stream: imu, kind: dropout, t_start_s: 3, t_end_s: 2}]")
                .find("'faults[0].t_end_s' must be greater than t_start_s"),
            std::string::npos);
  EXPECT_NE(parseError("faults: [{stream: imu, kind: dropout, t_start_s: 1, t_end_s: 2, params: {std_ms: 1}}]")
                .find("unknown key 'faults[0].params.std_ms'"),
            std::string::npos);
  EXPECT_NE(parseError("faults: [{stream: camera, kind: outlier, t_start_s: 1, t_end_s: 2}]")
                .find("outlier does not apply to the camera"),
            std::string::npos);
  EXPECT_NE(parseError("faults: [{stream: imu, kind: stuck, t_start_s: 1}]").find("needs 't_start_s' and 't_end_s'"),
            std::string::npos);
  EXPECT_NE(parseError("faults: {stream: imu}").find("'faults' must be a list"), std::string::npos);
}

TEST(SimScenarioLoader, RejectsInconsistentCombinations) {
  EXPECT_NE(parseError("trajectory: {circle_depth_m: 1001}").find("shallower than 'environment.seabed_depth_m'"),
            std::string::npos);
  EXPECT_NE(parseError("dvl: {min_altitude_m: 60}").find("'dvl.min_altitude_m' must be less than"),
            std::string::npos);
}

TEST(SimScenarioLoader, NamesAMissingFile) {
  Scenario s;
  std::string error;
  EXPECT_FALSE(loadScenario("/nonexistent/dive.yaml", &s, &error));
  EXPECT_EQ(error, "/nonexistent/dive.yaml: cannot open the scenario file");
}

}  // namespace
}  // namespace deepnav::sim
