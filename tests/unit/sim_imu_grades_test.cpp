// `imu.grade` in a scenario: the grade's table first, then the explicit keys, whatever their order.
#include <string>

#include <gtest/gtest.h>

#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensors/imu_grades.h"

namespace deepnav::sim {
namespace {

ImuConfig parseImu(const std::string& yaml) {
  Scenario s;
  std::string error;
  EXPECT_TRUE(parseScenario(yaml, "test.yaml", &s, &error)) << error;
  return s.imu;
}

TEST(SimImuGrades, AbsentGradeKeepsTheBuiltInDefaults) {
  EXPECT_EQ(parseImu("imu: {enabled: true}"), ImuConfig{});
}

TEST(SimImuGrades, EachGradeSetsItsDataSheetFigures) {
  const ImuConfig mems = parseImu("imu: {grade: mems}");
  EXPECT_DOUBLE_EQ(mems.gyro_noise_deg_per_sqrt_h, 0.6);  // MTi-300: 0.01 deg/s/sqrt(Hz)
  EXPECT_DOUBLE_EQ(mems.gyro_bias_instability_deg_per_h, 10.0);
  const ImuConfig tactical = parseImu("imu: {grade: tactical}");
  EXPECT_DOUBLE_EQ(tactical.gyro_noise_deg_per_sqrt_h, 0.15);  // STIM300
  EXPECT_DOUBLE_EQ(tactical.gyro_bias_instability_deg_per_h, 0.5);
  EXPECT_DOUBLE_EQ(tactical.gyro_scale_factor_ppm, 500.0);
  EXPECT_DOUBLE_EQ(tactical.accel_noise_mps_per_sqrt_h, 0.06);
  const ImuConfig navigation = parseImu("imu: {grade: navigation}");
  EXPECT_DOUBLE_EQ(navigation.gyro_noise_deg_per_sqrt_h, 0.002);  // HG9900
  EXPECT_DOUBLE_EQ(navigation.gyro_bias_instability_deg_per_h, 0.0035);
  // Ordered as the names say on the gyro figures.
  EXPECT_GT(mems.gyro_bias_instability_deg_per_h, tactical.gyro_bias_instability_deg_per_h);
  EXPECT_GT(tactical.gyro_bias_instability_deg_per_h, navigation.gyro_bias_instability_deg_per_h);
  EXPECT_GT(tactical.gyro_noise_deg_per_sqrt_h, navigation.gyro_noise_deg_per_sqrt_h);
  // (Not the accelerometer bias instability: the MTi-300's 15 ug is an in-run Allan floor, the HG9900's
  // 25 ug its overall bias figure, the only one its brochure gives; README "Sensor grades: IMU".)
  // The grade does not touch where and how often the IMU samples.
  EXPECT_EQ(tactical.rate_hz, ImuConfig{}.rate_hz);
  EXPECT_EQ(tactical.vibration_accel_rms_mps2, 0.0);
}

TEST(SimImuGrades, ExplicitKeysOverrideTheGradeWhateverTheirOrder) {
  const ImuConfig before = parseImu("imu:\n  gyro_noise_deg_per_sqrt_h: 0.3\n  grade: tactical\n");
  const ImuConfig after = parseImu("imu:\n  grade: tactical\n  gyro_noise_deg_per_sqrt_h: 0.3\n");
  EXPECT_EQ(before, after);
  EXPECT_DOUBLE_EQ(before.gyro_noise_deg_per_sqrt_h, 0.3);
  EXPECT_DOUBLE_EQ(before.gyro_bias_instability_deg_per_h, 0.5);  // the rest from the grade
}

TEST(SimImuGrades, BadGradeAndRangesNameTheKey) {
  Scenario s;
  std::string error;
  EXPECT_FALSE(parseScenario("imu: {grade: consumer}", "test.yaml", &s, &error));
  EXPECT_NE(error.find("'imu.grade' = consumer is not one of: mems, tactical, navigation"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("imu: {gyro_bias_correlation_time_s: 0}", "test.yaml", &s, &error));
  EXPECT_NE(error.find("'imu.gyro_bias_correlation_time_s' = 0 is out of range [1, 1e+06] s"), std::string::npos)
      << error;
  EXPECT_FALSE(parseScenario("imu: {p_imu_in_robot_m: [0, 0, 20]}", "test.yaml", &s, &error));
  EXPECT_NE(error.find("imu.p_imu_in_robot_m"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::sim
