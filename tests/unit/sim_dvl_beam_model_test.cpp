// The DVL's beam model: per-beam noise through the least-squares solution, 3-beam solutions, scale factor,
// misalignment, per-dive bias and random outliers, against the configured values. Tolerances are a few
// standard errors of the estimate at the sample size used (given at each check); seeds are fixed.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_dvl.h"
#include "sim_test_stats.h"
#include "tools/sim/rotation.h"
#include "tools/sim/sensors/dvl_beam_solver.h"
#include "tools/sim/sensors/dvl_model.h"

namespace deepnav::sim {
namespace {

using test::mean;
using test::makeDvl;
using test::noiselessDvlConfig;
using test::restingState;
using test::stddev;

// The beam model with nothing but the given terms: no per-axis or range noise, DVL at the robot origin.
DvlConfig beamModel() { return noiselessDvlConfig(); }

constexpr std::uint64_t kDvlSeed = 11;

KinematicState moving(const Eigen::Vector3d& v_odom_mps, double height_m = 2.0) {
  KinematicState s = restingState(height_m);
  s.v_robot_in_odom_mps = v_odom_mps;
  return s;
}

// Sample covariance of the velocity errors.
Eigen::Matrix3d errorCovariance(DvlModel& dvl, const KinematicState& s, int n, std::uint8_t expected_mask) {
  const Eigen::Vector3d v_true = dvl.trueVelocity_mps(s);
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d mean_err = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> err;
  for (int k = 0; k < n; ++k) {
    const DvlSample m = dvl.measure(s, TimeUs{k} * 100000);
    EXPECT_TRUE(m.valid);
    EXPECT_EQ(m.beam_valid_mask, expected_mask);
    err.push_back(m.v_dvl_mps - v_true);
    mean_err += err.back() / n;
  }
  for (const Eigen::Vector3d& e : err) sum += (e - mean_err) * (e - mean_err).transpose();
  return sum / (n - 1);
}

// Predicted covariance from the beam geometry: (B^T B)^-1 B^T S B (B^T B)^-1 over the beams in mask.
Eigen::Matrix3d predictedCovariance(const DvlModel& dvl, const DvlConfig& c, const Eigen::Vector3d& v_dvl,
                                    std::uint8_t mask) {
  std::array<Eigen::Vector3d, kDvlBeams> beams;
  std::array<double, kDvlBeams> u{}, sigma{};
  for (int i = 0; i < kDvlBeams; ++i) {
    beams[i] = dvl.beamInDvl(i);
    sigma[i] = c.beam_noise_fraction * std::abs(beams[i].dot(v_dvl)) + c.beam_noise_floor_mps;
  }
  Eigen::Vector3d v;
  Eigen::Matrix3d cov;
  EXPECT_TRUE(solveDvlBeams(beams, u, sigma, mask, &v, &cov));
  return cov;
}

// Each entry of the sample covariance against the prediction: variances within 5 % (relative standard
// error sqrt(2 / n) = 1 % at n = 20000), covariances within 0.04 in correlation (standard error 1/sqrt(n) = 0.007).
void expectCovarianceMatches(const Eigen::Matrix3d& sample, const Eigen::Matrix3d& predicted) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(sample(i, i) / predicted(i, i), 1.0, 0.05) << "axis " << i;
    for (int j = i + 1; j < 3; ++j) {
      const double norm = std::sqrt(predicted(i, i) * predicted(j, j));
      EXPECT_NEAR(sample(i, j) / norm, predicted(i, j) / norm, 0.04) << i << "," << j;
    }
  }
}

TEST(SimDvlBeamSolver, FourLevelBeamsGiveTheJanusVariances) {
  DvlModel dvl = makeDvl(beamModel(), kDvlSeed);
  std::array<Eigen::Vector3d, kDvlBeams> beams;
  for (int i = 0; i < kDvlBeams; ++i) beams[i] = dvl.beamInDvl(i);
  const Eigen::Vector3d v_true(0.3, -0.1, 0.05);
  std::array<double, kDvlBeams> u{}, sigma{};
  for (int i = 0; i < kDvlBeams; ++i) u[i] = beams[i].dot(v_true), sigma[i] = 0.01;
  Eigen::Vector3d v;
  Eigen::Matrix3d cov;
  ASSERT_TRUE(solveDvlBeams(beams, u, sigma, 0xF, &v, &cov));
  EXPECT_LT((v - v_true).norm(), 1e-14);
  const double sin_a = std::sin(30.0 * kDegToRad), cos_a = std::cos(30.0 * kDegToRad);
  EXPECT_NEAR(cov(0, 0), 1e-4 / (2.0 * sin_a * sin_a), 1e-18);
  EXPECT_NEAR(cov(1, 1), 1e-4 / (2.0 * sin_a * sin_a), 1e-18);
  EXPECT_NEAR(cov(2, 2), 1e-4 / (4.0 * cos_a * cos_a), 1e-18);
  EXPECT_NEAR(cov(0, 1), 0.0, 1e-18);
  ASSERT_TRUE(solveDvlBeams(beams, u, sigma, 0x7, &v, &cov));  // three beams: exact
  EXPECT_LT((v - v_true).norm(), 1e-14);
  EXPECT_FALSE(solveDvlBeams(beams, u, sigma, 0x3, &v, &cov));  // two beams: no solution
}

TEST(SimDvlBeamModel, PerBeamNoiseGivesTheGeometrysVelocityCovariance) {
  DvlConfig c = beamModel();
  c.beam_noise_fraction = 0.02;
  c.beam_noise_floor_mps = 0.002;
  c.mount_rpy_deg = {0.0, 0.0, 20.0};
  DvlModel dvl = makeDvl(c, kDvlSeed);
  const KinematicState s = moving({0.4, -0.25, 0.05});
  const Eigen::Vector3d v_dvl = dvl.trueVelocity_mps(s);
  const Eigen::Matrix3d predicted = predictedCovariance(dvl, c, v_dvl, 0xF);
  expectCovarianceMatches(errorCovariance(dvl, s, 20000, 0xF), predicted);
  const DvlSample m = dvl.measure(s, 0);
  EXPECT_LT((m.cov_v_dvl_mps2 - predicted).norm(), 1e-15);  // the stated covariance is the prediction
  EXPECT_DOUBLE_EQ(m.fom_mps, std::sqrt(predicted.trace() / 3.0));
}

// Pitched 20 deg nose down at 8 m with a 10 m window and beams fore, left, aft, right: the aft beam's
// vertical range is 8 cos 30 / cos 50 = 10.8 m, outside; the others (6.9, 8.5 m) lock.
TEST(SimDvlBeamModel, ThreeBeamSolutionWhenOneBeamIsLostIsValidWithItsOwnCovariance) {
  DvlConfig c = beamModel();
  c.beam_noise_floor_mps = 0.003;
  c.beam_azimuth_offset_deg = 0.0;
  c.max_altitude_m = 10.0;
  DvlModel dvl = makeDvl(c, kDvlSeed);
  KinematicState s = moving({0.2, 0.1, 0.0}, 8.0);
  s.q_odom_robot = Eigen::AngleAxisd(20.0 * kDegToRad, Eigen::Vector3d::UnitY());
  constexpr std::uint8_t kAllButAft = 0b1011;
  const DvlSample m = dvl.measure(s, 0);
  ASSERT_TRUE(m.valid);
  EXPECT_EQ(m.beam_valid_mask, kAllButAft);
  const Eigen::Matrix3d predicted = predictedCovariance(dvl, c, dvl.trueVelocity_mps(s), kAllButAft);
  EXPECT_LT((m.cov_v_dvl_mps2 - predicted).norm(), 1e-15);
  // Less redundancy, larger errors than the 4-beam solution's.
  EXPECT_GT(predicted.trace(), predictedCovariance(dvl, c, dvl.trueVelocity_mps(s), 0xF).trace());
  expectCovarianceMatches(errorCovariance(dvl, s, 20000, kAllButAft), predicted);
}

// Ratio of measured to true forward velocity: 2000 pings with 2 mm/s beam noise give a standard error
// of 1.4 * 2e-3 / 0.5 / sqrt(2000) = 1.3e-4 on the mean ratio; 6e-4 allowed.
TEST(SimDvlBeamModel, ScaleFactorShowsInTheMeanRatioOfMeasuredToTrueVelocity) {
  DvlConfig c = beamModel();
  c.beam_noise_floor_mps = 0.002;
  c.scale_factor_percent = 1.5;
  DvlModel dvl = makeDvl(c, kDvlSeed);
  const KinematicState s = moving({0.5, 0.0, 0.0});
  std::vector<double> ratio;
  for (int k = 0; k < 2000; ++k) ratio.push_back(dvl.measure(s, TimeUs{k} * 100000).v_dvl_mps.x() / 0.5);
  EXPECT_NEAR(mean(ratio), 1.015, 6e-4);
  EXPECT_DOUBLE_EQ(dvl.scale(), 1.015);
  // Ranges carry the same sound-speed error.
  EXPECT_NEAR(dvl.measure(s, 0).altitude_m, 2.0 * 1.015, 1e-12);
}

// The per-dive scale error over 400 dives (seeds): its sample std has a relative standard error of
// 1/sqrt(800) = 3.5 %, 12 % allowed; its mean 0 within 4 standard errors (0.5 / 20 = 0.025 %).
TEST(SimDvlBeamModel, ScaleFactorDrawnPerDiveHasTheConfiguredSigma) {
  DvlConfig c = beamModel();
  c.scale_factor_sigma_percent = 0.5;
  const KinematicState s = moving({0.5, 0.0, 0.0});
  std::vector<double> error_percent;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    DvlModel dvl = makeDvl(c, seed);
    const double ratio = dvl.measure(s, 0).v_dvl_mps.x() / 0.5;
    EXPECT_NEAR(ratio, dvl.scale(), 1e-12);
    error_percent.push_back((ratio - 1.0) * 100.0);
  }
  EXPECT_NEAR(stddev(error_percent), 0.5, 0.06);
  EXPECT_NEAR(mean(error_percent), 0.0, 0.1);
}

// A 2 deg yaw misalignment the board does not know: moving straight ahead at 0.5 m/s, the board's DVL
// frame sees -0.5 sin(2 deg) = -17.4 mm/s sideways. 2000 pings: standard error 6e-5 m/s, 3e-4 allowed.
TEST(SimDvlBeamModel, MisalignmentShowsInTheCrossAxisVelocity) {
  DvlConfig c = beamModel();
  c.beam_noise_floor_mps = 0.002;
  c.misalignment_rpy_deg = {0.0, 0.0, 2.0};
  DvlModel dvl = makeDvl(c, kDvlSeed);
  const KinematicState s = moving({0.5, 0.0, 0.0});
  std::vector<double> cross;
  for (int k = 0; k < 2000; ++k) cross.push_back(dvl.measure(s, TimeUs{k} * 100000).v_dvl_mps.y());
  EXPECT_NEAR(mean(cross), -0.5 * std::sin(2.0 * kDegToRad), 3e-4);
  // Noiseless, the reading is exactly the board-frame velocity rotated by the misalignment.
  c.beam_noise_floor_mps = 0.0;
  DvlModel exact = makeDvl(c, kDvlSeed);
  const Eigen::Vector3d v_board(0.5, 0.0, 0.0);
  const Eigen::Vector3d expected = rotationFromRpyDeg({0.0, 0.0, 2.0}).transpose() * v_board;
  EXPECT_LT((exact.measure(s, 0).v_dvl_mps - expected).norm(), 1e-14);
}

// Per-dive bias over 300 dives: relative standard error of the std 1/sqrt(600) = 4 %, 15 % allowed.
TEST(SimDvlBeamModel, VelocityBiasDrawnPerDiveAndConstantWithinIt) {
  DvlConfig c = beamModel();
  c.bias_sigma_mps = 0.002;
  const KinematicState s = moving({0.3, 0.0, 0.0});
  std::vector<double> bias_x;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    DvlModel dvl = makeDvl(c, seed);
    const Eigen::Vector3d first = dvl.measure(s, 0).v_dvl_mps - dvl.trueVelocity_mps(s);
    EXPECT_LT((first - dvl.bias_mps()).norm(), 1e-14);
    EXPECT_LT((dvl.measure(s, 100000).v_dvl_mps - dvl.trueVelocity_mps(s) - first).norm(), 1e-15);
    bias_x.push_back(first.x());
  }
  EXPECT_NEAR(stddev(bias_x) / 0.002, 1.0, 0.15);
}

// Outliers of 1 m/s on a beam move the solution by > 0.5 m/s; with 1 mm/s noise nothing else comes near
// 0.05 m/s. Each ping has an outlier with probability 1 - (1 - p)^4 = 0.1855 (p = 0.05): 4000 pings give a
// standard error of 0.006 on that fraction, 0.025 allowed.
TEST(SimDvlBeamModel, OutliersComeAtTheConfiguredProbability) {
  DvlConfig c = beamModel();
  c.beam_noise_floor_mps = 0.001;
  c.outlier_probability = 0.05;
  c.outlier_magnitude_mps = 1.0;
  DvlModel dvl = makeDvl(c, kDvlSeed);
  const KinematicState s = moving({0.2, 0.0, 0.0});
  const Eigen::Vector3d v_true = dvl.trueVelocity_mps(s);
  int hit = 0;
  constexpr int kPings = 4000;
  for (int k = 0; k < kPings; ++k)
    if ((dvl.measure(s, TimeUs{k} * 100000).v_dvl_mps - v_true).norm() > 0.05) ++hit;
  EXPECT_NEAR(static_cast<double>(hit) / kPings, 1.0 - std::pow(0.95, 4), 0.025);
}

TEST(SimDvlBeamModel, NewTermsDoNotShiftThePerAxisNoise) {
  // The per-axis noise keeps its draws: with only a fixed scale factor on, the per-axis errors are the
  // per-axis model's errors scaled with the velocity.
  DvlConfig per_axis;
  per_axis.p_dvl_in_robot_m = {0.0, 0.0, 0.0};
  DvlConfig with_scale = per_axis;
  with_scale.scale_factor_percent = 1e-9;
  DvlModel a = makeDvl(per_axis, kDvlSeed), b = makeDvl(with_scale, kDvlSeed);
  const KinematicState s = moving({0.3, 0.2, 0.0});
  for (int k = 0; k < 50; ++k) {
    const DvlSample ma = a.measure(s, TimeUs{k} * 200000), mb = b.measure(s, TimeUs{k} * 200000);
    EXPECT_LT((ma.v_dvl_mps - mb.v_dvl_mps).norm(), 1e-9);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(ma.beam_range_m[i], mb.beam_range_m[i], 1e-9);
  }
}

}  // namespace
}  // namespace deepnav::sim
