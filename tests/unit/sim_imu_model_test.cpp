#include "tools/sim/sensors/imu_model.h"

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_stats.h"

namespace deepnav::sim {
namespace {

using test::restingState;
using test::stddev;

ImuConfig whiteNoiseOnly() {
  ImuConfig c;
  c.gyro_bias_rw_deg_per_h_per_sqrt_h = 0.0;
  c.gyro_initial_bias_deg_per_h = 0.0;
  c.accel_bias_rw_mps2_per_sqrt_h = 0.0;
  c.accel_initial_bias_mps2 = 0.0;
  return c;
}

TEST(SimImuModel, ConvertsDataSheetDensitiesToPerSampleSigmas) {
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(ImuConfig{}, 1, &error)) << error;
  // 0.15 deg/sqrt(h) = 0.15 * pi/180 / 60 rad/sqrt(s); at 100 Hz sigma = density * sqrt(100).
  EXPECT_NEAR(imu.gyroNoiseSigma_radps(), 0.15 * std::numbers::pi / 180.0 / 60.0 * 10.0, 1e-15);
  // 0.03 m/s/sqrt(h) = 0.0005 m/s^2/sqrt(Hz).
  EXPECT_NEAR(imu.accelNoiseSigma_mps2(), 0.0005 * 10.0, 1e-15);
  // 0.5 deg/h/sqrt(h) per step of 0.01 s.
  EXPECT_NEAR(imu.gyroBiasStepSigma_radps(), 0.5 * std::numbers::pi / 180.0 / 3600.0 / 60.0 * 0.1, 1e-18);
}

TEST(SimImuModel, WhiteNoiseStdMatchesTheConfiguration) {
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(whiteNoiseOnly(), 7, &error)) << error;
  const KinematicState rest = restingState();
  std::vector<double> gyro[3], accel[3];
  for (int k = 0; k < 20000; ++k) {
    const ImuSample s = imu.measure(rest, k * 10000);
    for (int i = 0; i < 3; ++i) {
      gyro[i].push_back(s.w_imu_radps[i]);
      accel[i].push_back(s.f_imu_mps2[i] - rest.f_robot_mps2[i]);
    }
  }
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(stddev(gyro[i]) / imu.gyroNoiseSigma_radps(), 1.0, 0.05) << "axis " << i;
    EXPECT_NEAR(stddev(accel[i]) / imu.accelNoiseSigma_mps2(), 1.0, 0.05) << "axis " << i;
    EXPECT_NEAR(test::mean(gyro[i]), 0.0, 4.0 * imu.gyroNoiseSigma_radps() / std::sqrt(20000.0));
  }
}

TEST(SimImuModel, BiasRandomWalkVarianceGrowsLinearly) {
  // GIVEN many independent IMUs with only a bias random walk
  ImuConfig c = whiteNoiseOnly();
  c.gyro_bias_rw_deg_per_h_per_sqrt_h = 100.0;
  c.accel_bias_rw_mps2_per_sqrt_h = 0.5;
  const KinematicState rest = restingState();
  constexpr int kUnits = 1000, kSteps = 400;
  std::vector<double> gyro_half, gyro_end, accel_end;
  double step_gyro = 0.0, step_accel = 0.0;
  for (int u = 0; u < kUnits; ++u) {
    ImuModel imu;
    std::string error;
    ASSERT_TRUE(imu.init(c, 1000 + u, &error));
    step_gyro = imu.gyroBiasStepSigma_radps();
    step_accel = imu.accelBiasStepSigma_mps2();
    for (int k = 0; k < kSteps; ++k) {
      imu.measure(rest, k * 10000);
      if (k + 1 == kSteps / 2)
        for (int i = 0; i < 3; ++i) gyro_half.push_back(imu.gyroBias_radps()[i]);
    }
    for (int i = 0; i < 3; ++i) {
      gyro_end.push_back(imu.gyroBias_radps()[i]);
      accel_end.push_back(imu.accelBias_mps2()[i]);
    }
  }
  // THEN the bias variance after n steps is n * step^2 (3000 walks: 2.6 % standard error)
  auto variance = [](const std::vector<double>& x) { return std::pow(stddev(x), 2); };
  EXPECT_NEAR(variance(gyro_end) / (kSteps * step_gyro * step_gyro), 1.0, 0.1);
  EXPECT_NEAR(variance(gyro_half) / (kSteps / 2 * step_gyro * step_gyro), 1.0, 0.1);
  EXPECT_NEAR(variance(accel_end) / (kSteps * step_accel * step_accel), 1.0, 0.1);
}

TEST(SimImuModel, InitialBiasesAreDrawnWithTheConfiguredSigma) {
  ImuConfig c = whiteNoiseOnly();
  c.gyro_initial_bias_deg_per_h = 3.0;
  c.accel_initial_bias_mps2 = 0.005;
  std::vector<double> gyro, accel;
  for (int u = 0; u < 1000; ++u) {
    ImuModel imu;
    std::string error;
    ASSERT_TRUE(imu.init(c, 5000 + u, &error));
    for (int i = 0; i < 3; ++i) {
      gyro.push_back(imu.gyroBias_radps()[i]);
      accel.push_back(imu.accelBias_mps2()[i]);
    }
  }
  EXPECT_NEAR(stddev(gyro) / (3.0 * std::numbers::pi / 180.0 / 3600.0), 1.0, 0.06);
  EXPECT_NEAR(stddev(accel) / 0.005, 1.0, 0.06);
}

TEST(SimImuModel, MountingRotationExpressesTruthInTheImuFrame) {
  ImuConfig c = whiteNoiseOnly();
  c.gyro_noise_deg_per_sqrt_h = 0.0;
  c.accel_noise_mps_per_sqrt_h = 0.0;
  c.mount_rpy_deg = {0.0, 0.0, 90.0};  // IMU x along robot y
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(c, 1, &error));
  KinematicState s = restingState();
  s.w_robot_radps = {0.0, 0.2, 0.0};
  s.f_robot_mps2 = {0.0, 1.0, 9.8};
  const ImuSample m = imu.measure(s, 0);
  EXPECT_LT((m.w_imu_radps - Eigen::Vector3d(0.2, 0.0, 0.0)).norm(), 1e-12);
  EXPECT_LT((m.f_imu_mps2 - Eigen::Vector3d(1.0, 0.0, 9.8)).norm(), 1e-12);
}

}  // namespace
}  // namespace deepnav::sim
