// nav/metrics: chi-square quantiles and the NEES of position and heading.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "nav/metrics/chi_square.h"
#include "nav/metrics/nees.h"

namespace deepnav {
namespace {

TEST(MetricsChiSquare, QuantilesMatchTheTables) {
  // Reference values: scipy.stats.chi2.ppf (and 2 ln 2, the median of 2 dof, in closed form).
  EXPECT_NEAR(chiSquareQuantile(0.025, 1), 9.82069117e-4, 1e-10);
  EXPECT_NEAR(chiSquareQuantile(0.975, 1), 5.02388619, 1e-7);
  EXPECT_NEAR(chiSquareQuantile(0.025, 3), 0.21579528, 1e-7);
  EXPECT_NEAR(chiSquareQuantile(0.975, 3), 9.3484036, 1e-6);
  EXPECT_NEAR(chiSquareQuantile(0.5, 2), 2.0 * std::log(2.0), 1e-10);
  // The band of the mean of 100 samples of 3 dof: chi-square of 300 dof over 100.
  const ChiSquareBand mean = chiSquareMeanBand(3, 100, 0.05);
  EXPECT_NEAR(mean.lo, 2.53912323, 1e-7);
  EXPECT_NEAR(mean.hi, 3.49874469, 1e-7);
  // A long dive: 12000 ticks of 3 dof (36000 dof) still converges, around the mean 3.
  const ChiSquareBand dive = chiSquareMeanBand(3, 12000, 0.05);
  EXPECT_NEAR(0.5 * (dive.lo + dive.hi), 3.0, 1e-3);
  EXPECT_NEAR(dive.hi - dive.lo, 2.0 * 1.959964 * std::sqrt(6.0 / 12000.0), 1e-3);
}

TEST(MetricsNees, HandComputedPositionAndHeading) {
  // e = (0.1, 0, 0.2), P = diag(0.01, 1, 0.04): 0.01/0.01 + 0.04/0.04 = 2
  const Eigen::Matrix3d P = Eigen::Vector3d(0.01, 1.0, 0.04).asDiagonal();
  EXPECT_NEAR(positionNees(Eigen::Vector3d(1.1, 2.0, 3.2), Eigen::Vector3d(1, 2, 3), P), 2.0, 1e-12);
  EXPECT_TRUE(std::isnan(positionNees(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), Eigen::Matrix3d::Zero())));
  // The truth is the estimate turned by 0.1 rad about the odom z axis (left perturbation), under a tilt
  const Eigen::Quaterniond q_est(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitX()));
  const Eigen::Quaterniond q_true = Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitZ())) * q_est;
  EXPECT_NEAR(headingError(q_est, q_true), 0.1, 1e-12);
  EXPECT_NEAR(headingNees(q_est, q_true, 0.0025), 4.0, 1e-9);
}

// Errors drawn from N(0, P_true); the filter reports P_reported. Returns the position and heading NEES.
struct Draws {
  std::vector<double> position, heading;
};
Draws simulate(double reported_over_true, int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::Matrix3d P_true;
  P_true << 4e-4, 1e-4, 0, 1e-4, 9e-4, -2e-4, 0, -2e-4, 1e-4;
  const Eigen::Matrix3d L = P_true.llt().matrixL();
  const double sigma_yaw = 0.01;
  const Eigen::Quaterniond q_est(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
  Draws d;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d e = L * Eigen::Vector3d(normal(rng), normal(rng), normal(rng));
    d.position.push_back(positionNees(e, Eigen::Vector3d::Zero(), reported_over_true * P_true));
    const Eigen::Quaterniond q_true =
        Eigen::Quaterniond(Eigen::AngleAxisd(sigma_yaw * normal(rng), Eigen::Vector3d::UnitZ())) * q_est;
    d.heading.push_back(headingNees(q_est, q_true, reported_over_true * sigma_yaw * sigma_yaw));
  }
  return d;
}

TEST(MetricsNees, AConsistentEstimatorIsInsideTheBand) {
  // GIVEN 4000 errors drawn from the covariance the filter reports
  const Draws d = simulate(1.0, 4000, 11);
  const NeesSummary p = summarizeNees(d.position, 3);
  const NeesSummary h = summarizeNees(d.heading, 1);
  // THEN the mean NEES is the dof (std of the mean sqrt(2 k / N): 0.039 for k = 3, 0.022 for k = 1; 4
  // sigma) and inside the band of the mean; 95 % of the samples are inside the per-sample band (binomial
  // std sqrt(0.95 0.05 / 4000) = 0.0034; 4 sigma)
  EXPECT_NEAR(p.mean, 3.0, 0.16);
  EXPECT_NEAR(h.mean, 1.0, 0.09);
  EXPECT_GT(p.mean, p.mean_band.lo);
  EXPECT_LT(p.mean, p.mean_band.hi);
  EXPECT_GT(h.mean, h.mean_band.lo);
  EXPECT_LT(h.mean, h.mean_band.hi);
  EXPECT_NEAR(p.in_band_fraction, 0.95, 0.014);
  EXPECT_NEAR(h.in_band_fraction, 0.95, 0.014);
  EXPECT_NEAR(p.above_fraction, 0.025, 0.01);
  EXPECT_EQ(p.count, 4000u);
  EXPECT_NEAR(p.band.hi, 9.3484036, 1e-6);
}

TEST(MetricsNees, AnOverconfidentEstimatorIsAboveTheBand) {
  // GIVEN a filter reporting a quarter of its real covariance (sigma halved)
  const Draws d = simulate(0.25, 4000, 12);
  const NeesSummary p = summarizeNees(d.position, 3);
  const NeesSummary h = summarizeNees(d.heading, 1);
  // THEN the mean NEES is 4 k, far above the band of the mean, and only P(0.054 < chi2_3 < 2.34) = 0.49
  // of the position samples (heading: P(0.00025 < chi2_1 < 1.256) = 0.72) are in the per-sample band
  EXPECT_NEAR(p.mean, 12.0, 0.7);
  EXPECT_NEAR(h.mean, 4.0, 0.35);
  EXPECT_GT(p.mean, p.mean_band.hi);
  EXPECT_GT(h.mean, h.mean_band.hi);
  EXPECT_NEAR(p.in_band_fraction, 0.491, 0.032);
  EXPECT_NEAR(h.in_band_fraction, 0.725, 0.03);
  EXPECT_GT(p.above_fraction, 0.45);
}

TEST(MetricsNees, NonFiniteSamplesAreLeftOut) {
  const std::vector<double> v = {1.0, std::nan(""), 2.0};
  const NeesSummary s = summarizeNees(v, 1);
  EXPECT_EQ(s.count, 2u);
  EXPECT_DOUBLE_EQ(s.mean, 1.5);
  const NeesSummary none = summarizeNees(std::vector<double>{}, 3);
  EXPECT_EQ(none.count, 0u);
}

}  // namespace
}  // namespace deepnav
