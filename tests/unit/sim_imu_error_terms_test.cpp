// The IMU's systematic and environmental error terms: scale factor and misalignment (recovered as on a
// rate table), the lever-arm acceleration, the Gauss-Markov bias and the thruster vibration.
#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_stats.h"
#include "tools/sim/sensors/imu_gauss_markov.h"
#include "tools/sim/sensors/imu_grades.h"
#include "tools/sim/sensors/imu_model.h"
#include "tools/sim/trajectory.h"

namespace deepnav::sim {
namespace {

using test::restingState;
using test::stddev;

ImuConfig noiseFree() {
  ImuConfig c;
  c.gyro_noise_deg_per_sqrt_h = 0.0;
  c.gyro_bias_rw_deg_per_h_per_sqrt_h = 0.0;
  c.gyro_initial_bias_deg_per_h = 0.0;
  c.accel_noise_mps_per_sqrt_h = 0.0;
  c.accel_bias_rw_mps2_per_sqrt_h = 0.0;
  c.accel_initial_bias_mps2 = 0.0;
  return c;
}

TEST(SimImuErrorTerms, ScaleFactorAndMisalignmentAreDrawnWithTheConfiguredSigmas) {
  ImuConfig c = noiseFree();
  c.gyro_scale_factor_ppm = 500.0;
  c.gyro_misalignment_mrad = 1.0;
  c.accel_scale_factor_ppm = 300.0;
  c.accel_misalignment_mrad = 2.0;
  std::vector<double> gyro_scale, gyro_cross, accel_scale, accel_cross;
  for (int u = 0; u < 2000; ++u) {
    ImuModel imu;
    std::string error;
    ASSERT_TRUE(imu.init(c, 9000 + u, &error));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double g = imu.gyroScaleMisalignment()(i, j), a = imu.accelScaleMisalignment()(i, j);
        (i == j ? gyro_scale : gyro_cross).push_back(i == j ? g - 1.0 : g);
        (i == j ? accel_scale : accel_cross).push_back(i == j ? a - 1.0 : a);
      }
  }
  // 6000 scale factors, 12000 cross terms: standard error of a sigma 1/sqrt(2n) < 0.92 %; bound 3 %.
  EXPECT_NEAR(stddev(gyro_scale) / 500e-6, 1.0, 0.03);
  EXPECT_NEAR(stddev(gyro_cross) / 1e-3, 1.0, 0.03);
  EXPECT_NEAR(stddev(accel_scale) / 300e-6, 1.0, 0.03);
  EXPECT_NEAR(stddev(accel_cross) / 2e-3, 1.0, 0.03);
}

TEST(SimImuErrorTerms, RateTableRecoversTheScaleFactorAndMisalignmentOfATacticalUnit) {
  // GIVEN a tactical-grade unit with all its noise and biases, at 100 Hz
  ImuConfig c;
  applyImuGrade(ImuGrade::kTactical, &c);
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(c, 4242, &error)) << error;
  // WHEN it turns at +-1 rad/s about each axis and feels +-g along it, the sign alternating every sample
  // (the biases drift by far less than the noise between two samples, so the difference cancels them)
  constexpr int kPairs = 20000;
  constexpr double kRate_radps = 1.0, kForce_mps2 = 9.80665;
  Eigen::Matrix3d T_gyro, T_accel;
  TimeUs t_us = 0;
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d gyro_diff = Eigen::Vector3d::Zero(), accel_diff = Eigen::Vector3d::Zero();
    for (int k = 0; k < 2 * kPairs; ++k, t_us += 10000) {
      const double sign = (k % 2 == 0) ? 1.0 : -1.0;
      KinematicState s = restingState();
      s.w_robot_radps = sign * kRate_radps * Eigen::Vector3d::Unit(j);
      s.f_robot_mps2 = sign * kForce_mps2 * Eigen::Vector3d::Unit(j);
      const ImuSample m = imu.measure(s, t_us);
      gyro_diff += sign * m.w_imu_radps;
      accel_diff += sign * m.f_imu_mps2;
    }
    T_gyro.col(j) = gyro_diff / (2.0 * kPairs * kRate_radps);
    T_accel.col(j) = accel_diff / (2.0 * kPairs * kForce_mps2);
  }
  // THEN the recovered matrices are this dive's T_g and T_a. Standard error of one element: the white
  // noise sigma / (input sqrt(2 kPairs)) = 2.2 ppm (gyro) and 3.6 ppm (accel); bound 5 standard errors.
  const double gyro_se = imu.gyroNoiseSigma_radps() / (kRate_radps * std::sqrt(2.0 * kPairs));
  const double accel_se = imu.accelNoiseSigma_mps2() / (kForce_mps2 * std::sqrt(2.0 * kPairs));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(T_gyro(i, j), imu.gyroScaleMisalignment()(i, j), 5.0 * gyro_se) << i << "," << j;
      EXPECT_NEAR(T_accel(i, j), imu.accelScaleMisalignment()(i, j), 5.0 * accel_se) << i << "," << j;
    }
  // and the errors are there to be found (500 ppm and 1 mrad are 200 and 400 standard errors).
  EXPECT_GT((T_gyro - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff(), 50.0 * gyro_se);
  std::printf("[imu] rate table: T_g - I (ppm)\n");
  for (int i = 0; i < 3; ++i)
    std::printf("[imu]   %8.1f %8.1f %8.1f   (true %8.1f %8.1f %8.1f)\n", 1e6 * (T_gyro(i, 0) - (i == 0)),
                1e6 * (T_gyro(i, 1) - (i == 1)), 1e6 * (T_gyro(i, 2) - (i == 2)),
                1e6 * (imu.gyroScaleMisalignment()(i, 0) - (i == 0)), 1e6 * (imu.gyroScaleMisalignment()(i, 1) - (i == 1)),
                1e6 * (imu.gyroScaleMisalignment()(i, 2) - (i == 2)));
}

TEST(SimImuErrorTerms, LeverArmAddsTangentialAndCentripetalAcceleration) {
  ImuConfig c = noiseFree();
  c.p_imu_in_robot_m = {0.5, 0.0, 0.0};
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(c, 1, &error));
  KinematicState s = restingState();
  s.w_robot_radps = {0.0, 0.0, 2.0};
  s.alpha_robot_radps2 = {0.0, 0.0, 3.0};
  // alpha x r = (0, 3 * 0.5, 0); w x (w x r) = (-2^2 * 0.5, 0, 0).
  const ImuSample m = imu.measure(s, 0);
  EXPECT_LT((m.f_imu_mps2 - (s.f_robot_mps2 + Eigen::Vector3d(-2.0, 1.5, 0.0))).norm(), 1e-12);
  EXPECT_LT((m.w_imu_radps - s.w_robot_radps).norm(), 1e-12);  // a rigid body turns as one
}

Trajectory defaultTrajectory() {
  Trajectory trajectory;
  std::string error;
  EXPECT_TRUE(trajectory.init(TrajectoryConfig{}, PanelGeometry{}, 1000.0, 9.80665, &error)) << error;
  return trajectory;
}

TEST(SimImuErrorTerms, AngularAccelerationIsTheDerivativeOfTheBodyRate) {
  const Trajectory trajectory = defaultTrajectory();
  // Central difference, h = 1e-4 s: truncation h^2 / 6 |w'''| < 1e-8 for rates of ~1 rad/s varying over
  // seconds; rounding 1e-16 / 1e-4 = 1e-12. Bound 1e-7 rad/s^2.
  constexpr double h = 1e-4;
  double max_alpha = 0.0;
  for (double t = 0.5; t < 110.0; t += 1.37) {
    const Eigen::Vector3d numeric =
        (trajectory.stateAt(t + h).w_robot_radps - trajectory.stateAt(t - h).w_robot_radps) / (2.0 * h);
    const Eigen::Vector3d alpha = trajectory.stateAt(t).alpha_robot_radps2;
    EXPECT_LT((alpha - numeric).norm(), 1e-7) << "t = " << t;
    max_alpha = std::max(max_alpha, alpha.norm());
  }
  EXPECT_GT(max_alpha, 1e-3);  // the dive does accelerate in rotation
}

TEST(SimImuErrorTerms, LeverArmSpecificForceMatchesTheMotionOfTheImuPoint) {
  // The accelerometer at r on the moving robot against R^T (d2/dt2 (p + R r) - g) by central differences
  // (h = 1e-3 s: truncation h^2 / 12 |p''''| ~ 1e-7, rounding 1e-16 * 1000 m / h^2 = 1e-10).
  const Trajectory trajectory = defaultTrajectory();
  ImuConfig c = noiseFree();
  c.p_imu_in_robot_m = {0.4, -0.3, 0.25};
  const Eigen::Vector3d r(0.4, -0.3, 0.25);
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(c, 1, &error));
  auto point = [&](double t) {
    const KinematicState s = trajectory.stateAt(t);
    return Eigen::Vector3d(s.p_robot_in_odom_m + s.q_odom_robot * r);
  };
  constexpr double h = 1e-3;
  double max_lever_term = 0.0;
  for (double t = 0.5; t < 110.0; t += 2.11) {
    const KinematicState s = trajectory.stateAt(t);
    const Eigen::Vector3d a_point = (point(t + h) - 2.0 * point(t) + point(t - h)) / (h * h);
    const Eigen::Vector3d expected = s.q_odom_robot.conjugate() * (a_point - Eigen::Vector3d(0.0, 0.0, -9.80665));
    const ImuSample m = imu.measure(s, 0);
    EXPECT_LT((m.f_imu_mps2 - expected).norm(), 1e-6) << "t = " << t;
    max_lever_term = std::max(max_lever_term, (m.f_imu_mps2 - s.f_robot_mps2).norm());
  }
  EXPECT_GT(max_lever_term, 1e-4);  // the lever arm's term is far above the tolerance
}

TEST(SimImuErrorTerms, ReportedBiasIsTheAdditiveBiasInTheNextSample) {
  // White noise off, every bias on: the sample minus the truth is exactly the bias reported before it.
  ImuConfig c;
  applyImuGrade(ImuGrade::kMems, &c);
  c.gyro_noise_deg_per_sqrt_h = 0.0;
  c.accel_noise_mps_per_sqrt_h = 0.0;
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(c, 77, &error));
  const KinematicState rest = restingState();
  for (int k = 0; k < 1000; ++k) {
    const Eigen::Vector3d b_g = imu.gyroBias_radps(), b_a = imu.accelBias_mps2();
    const ImuSample m = imu.measure(rest, k * 10000);
    ASSERT_EQ(m.w_imu_radps - rest.w_robot_radps, b_g) << k;
    // T_a multiplies gravity: remove it with this dive's matrix.
    ASSERT_LT((m.f_imu_mps2 - imu.accelScaleMisalignment() * rest.f_robot_mps2 - b_a).norm(), 1e-13) << k;
  }
}

TEST(SimImuErrorTerms, GaussMarkovBiasIsStationaryWithSigmaFromTheAllanFloor) {
  // Only the Gauss-Markov term: over many units its spread is sigma_GM = B / 0.6174 at the start and
  // after a correlation time (stationary), and the correlation after one T is exp(-1).
  ImuConfig c = noiseFree();
  c.gyro_bias_instability_deg_per_h = 1.0;
  c.gyro_bias_correlation_time_s = 2.0;
  c.rate_hz = 100.0;
  const double sigma_gm = 1.0 * std::numbers::pi / 180.0 / 3600.0 / kGaussMarkovAdevPeakOverSigma;
  std::vector<double> start, later;
  double cross = 0.0;
  for (int u = 0; u < 3000; ++u) {
    ImuModel imu;
    std::string error;
    ASSERT_TRUE(imu.init(c, 20000 + u, &error));
    const Eigen::Vector3d b0 = imu.gyroBias_radps();
    for (int k = 0; k < 200; ++k) imu.measure(restingState(), k * 10000);  // 2 s = T
    const Eigen::Vector3d b1 = imu.gyroBias_radps();
    for (int i = 0; i < 3; ++i) {
      start.push_back(b0[i]);
      later.push_back(b1[i]);
      cross += b0[i] * b1[i];
    }
  }
  // 9000 values: standard error of a sigma 0.75 %, of a correlation (1 - rho^2) / sqrt(n) = 0.9 %.
  EXPECT_NEAR(stddev(start) / sigma_gm, 1.0, 0.03);
  EXPECT_NEAR(stddev(later) / sigma_gm, 1.0, 0.03);
  EXPECT_NEAR(cross / 9000.0 / (sigma_gm * sigma_gm), std::exp(-1.0), 0.03);
}

// Amplitude of the component of y at frequency f (sample rate r) by a single DFT bin.
double toneAmplitude(const std::vector<double>& y, double f_hz, double rate_hz) {
  std::complex<double> sum = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k)
    sum += y[k] * std::polar(1.0, -2.0 * std::numbers::pi * f_hz * static_cast<double>(k) / rate_hz);
  return 2.0 * std::abs(sum) / static_cast<double>(y.size());
}

TEST(SimImuErrorTerms, VibrationRmsMatchesTheKeysAndTonesAliasAtTheImuRate) {
  ImuConfig c = noiseFree();
  c.vibration_accel_rms_mps2 = 0.5;
  c.vibration_gyro_rms_deg_per_s = 2.0;
  c.vibration_frequencies_hz = {73.0, 118.0, 161.0};
  ImuModel imu;
  std::string error;
  ASSERT_TRUE(imu.init(c, 5, &error));
  const KinematicState rest = restingState();
  constexpr int kSamples = 20000;  // 200 s at 100 Hz
  std::vector<double> gyro[3], accel[3];
  for (int k = 0; k < kSamples; ++k) {
    const ImuSample m = imu.measure(rest, k * 10000);
    for (int i = 0; i < 3; ++i) {
      gyro[i].push_back(m.w_imu_radps[i]);
      accel[i].push_back(m.f_imu_mps2[i] - rest.f_robot_mps2[i]);
    }
  }
  // rms: the broadband quarter of the power has a variance standard error sqrt(2 / N) = 1 %, i.e.
  // 0.25 % of the total; the tones' sample mean square is within 1 / N of 1/2. Bound 2 %.
  auto rms = [](const std::vector<double>& x) {
    double sum = 0.0;
    for (double v : x) sum += v * v;
    return std::sqrt(sum / static_cast<double>(x.size()));
  };
  const double gyro_rms_radps = 2.0 * std::numbers::pi / 180.0;
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(rms(accel[i]) / 0.5, 1.0, 0.02) << "axis " << i;
    EXPECT_NEAR(rms(gyro[i]) / gyro_rms_radps, 1.0, 0.02) << "axis " << i;
  }
  // Aliasing: sampled at 100 Hz without an anti-aliasing filter, 73, 118 and 161 Hz appear at 27, 18
  // and 39 Hz with the tone amplitude A = rms sqrt(2 * 0.75 / 3); a frequency with no tone (10 Hz) holds
  // only broadband noise, 2 sigma_n / sqrt(N) ~ 0.004 A. All these bins are exact (N f / r integer).
  const double A = 0.5 * std::sqrt(0.5);
  for (double alias_hz : {27.0, 18.0, 39.0}) EXPECT_NEAR(toneAmplitude(accel[0], alias_hz, 100.0) / A, 1.0, 0.03);
  EXPECT_LT(toneAmplitude(accel[0], 10.0, 100.0), 0.05 * A);
}

TEST(SimImuErrorTerms, SwitchingATermOnLeavesTheWhiteNoiseSequenceAlone) {
  // The new terms draw from their own sub-streams: with a lever arm, vibration and a Gauss-Markov bias on,
  // the default unit's white noise, turn-on and random-walk biases are the same numbers.
  ImuConfig base;
  ImuConfig extra = base;
  extra.accel_scale_factor_ppm = 300.0;
  extra.vibration_gyro_rms_deg_per_s = 0.5;
  extra.gyro_bias_instability_deg_per_h = 1.0;
  ImuModel a, b;
  std::string error;
  ASSERT_TRUE(a.init(base, 3, &error));
  ASSERT_TRUE(b.init(extra, 3, &error));
  const KinematicState rest = restingState();
  for (int k = 0; k < 100; ++k) {
    const ImuSample sa = a.measure(rest, k * 10000);
    const ImuSample sb = b.measure(rest, k * 10000);
    // Accel: only the scale factor differs (on gravity), the noise is identical.
    const Eigen::Vector3d accel_extra = (b.accelScaleMisalignment() - Eigen::Matrix3d::Identity()) * rest.f_robot_mps2;
    EXPECT_LT((sb.f_imu_mps2 - sa.f_imu_mps2 - accel_extra).norm(), 1e-12);
  }
  EXPECT_EQ(a.accelBias_mps2(), b.accelBias_mps2());
}

}  // namespace
}  // namespace deepnav::sim
