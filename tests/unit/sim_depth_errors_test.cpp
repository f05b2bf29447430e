// Depth errors: the density error as a depth scale factor, the pressure quantisation step and the
// drift rate, each recovered from the simulated stream; the depth grades in the loader.
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_stats.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensors/depth_model.h"

namespace deepnav::sim {
namespace {

using test::mean;
using test::restingState;
using test::stddev;

constexpr double kRhoG = 1028.0 * 9.80665;

// The sensor at `depth_m` (environment defaults: odometry origin at 1000 m).
KinematicState atDepth(double depth_m) { return restingState(1000.0 - depth_m); }

// Least-squares slope and intercept of y against x.
std::pair<double, double> lineFit(const std::vector<double>& x, const std::vector<double>& y) {
  const double mx = mean(x), my = mean(y);
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return {sxy / sxx, my - sxy / sxx * mx};
}

TEST(SimDepthErrors, DensityErrorIsADepthScaleFactor) {
  DepthConfig c;  // noise 0.02 m
  c.density_error_kgpm3 = 5.0;  // true mean density 1033 against the nominal 1028
  DepthModel depth;
  std::string error;
  ASSERT_TRUE(depth.init(c, EnvironmentConfig{}, 5, &error)) << error;
  EXPECT_NEAR(depth.scaleFactor(), 1033.0 / 1028.0, 1e-15);
  std::vector<double> truth_m, measured_m;
  for (int k = 0; k < 10000; ++k) {
    const double d = 100.0 + 0.09 * k;  // 100 .. 1000 m
    truth_m.push_back(d);
    measured_m.push_back(depth.measure(atDepth(d), k).depth_m);
  }
  const auto [slope, intercept] = lineFit(truth_m, measured_m);
  // sd of the slope: 0.02 m / (sqrt(10000) * 260 m) = 7.7e-7; 5e-6 is > 6 sigma.
  EXPECT_NEAR(slope, 1033.0 / 1028.0, 5e-6);
  EXPECT_NEAR(intercept, 0.0, 0.005);
  std::printf("[depth] scale factor configured %.6f, recovered %.6f\n", 1033.0 / 1028.0, slope);
}

TEST(SimDepthErrors, PressureIsQuantisedToTheResolution) {
  DepthConfig c;
  c.noise_m = 0.0;
  c.resolution_pa = 400.0;
  DepthModel depth;
  std::string error;
  ASSERT_TRUE(depth.init(c, EnvironmentConfig{}, 5, &error)) << error;
  std::set<double> levels;
  std::vector<double> err_pa;
  for (int k = 0; k < 20000; ++k) {
    const double d = 990.0 + 1e-4 * k;  // 2 m in 0.1 mm steps: 2 rho g / 400 = 50 quantisation steps
    const DepthSample s = depth.measure(atDepth(d), k);
    ASSERT_NEAR(std::remainder(s.pressure_pa, 400.0), 0.0, 1e-6);
    levels.insert(s.pressure_pa);
    err_pa.push_back(s.pressure_pa - (101325.0 + kRhoG * d));
    ASSERT_LE(std::abs(err_pa.back()), 200.0 + 1e-6);
  }
  // Consecutive levels one step apart, and the error uniform over a step: sd = 400 / sqrt(12).
  double smallest_step = 1e9;
  for (auto it = std::next(levels.begin()); it != levels.end(); ++it)
    smallest_step = std::min(smallest_step, *it - *std::prev(it));
  EXPECT_NEAR(smallest_step, 400.0, 1e-6);
  EXPECT_NEAR(stddev(err_pa) / (400.0 / std::sqrt(12.0)), 1.0, 0.02);
  EXPECT_NEAR(mean(err_pa), 0.0, 8.0);  // the partial step at the sweep's ends: at most 200 Pa / 50 steps
}

TEST(SimDepthErrors, DriftRateIsRecovered) {
  DepthConfig c;  // noise 0.02 m
  c.drift_m_per_h = 0.05;
  DepthModel depth;
  std::string error;
  ASSERT_TRUE(depth.init(c, EnvironmentConfig{}, 8, &error)) << error;
  std::vector<double> t_h, err_m;
  for (int k = 0; k <= 36000; ++k) {  // one hour at 10 Hz
    const TimeUs t_us = static_cast<TimeUs>(k) * 100000;
    t_h.push_back(static_cast<double>(t_us) / 3600e6);
    err_m.push_back(depth.measure(atDepth(998.5), t_us).depth_m - 998.5);
  }
  const auto [rate, offset] = lineFit(t_h, err_m);
  // sd of the rate: 0.02 m / (sqrt(36001) * 0.289 h) = 3.7e-4 m/h; 0.002 m/h is > 5 sigma.
  EXPECT_NEAR(rate, 0.05, 0.002);
  EXPECT_NEAR(offset, 0.0, 0.001);
  std::printf("[depth] drift configured 0.05 m/h, recovered %.4f m/h\n", rate);
}

TEST(SimDepthErrors, OffTermsLeaveTheStreamBitIdentical) {
  DepthModel a;
  std::string error;
  ASSERT_TRUE(a.init(DepthConfig{}, EnvironmentConfig{}, 13, &error));
  // The pre-change formula, evaluated here: p_atm + rho g d + noise with the model's own noise stream.
  NormalRng rng(13);
  for (int k = 0; k < 1000; ++k) {
    const double d = 990.0 + 0.01 * k;
    const DepthSample s = a.measure(atDepth(d), k);
    const double p = 101325.0 + kRhoG * a.trueDepth_m(atDepth(d)) + rng.normal(a.noiseSigma_pa());
    ASSERT_EQ(s.pressure_pa, p);
    ASSERT_EQ(s.depth_m, (p - 101325.0) / kRhoG);
  }
}

TEST(SimDepthGrades, GradeSetsItsFiguresAndExplicitKeysOverride) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario("depth: {grade: strain_gauge}\n", "t.yaml", &s, &error)) << error;
  EXPECT_EQ(s.depth.grade, DepthGrade::kStrainGauge);
  EXPECT_NEAR(s.depth.resolution_pa, 400.0, 1e-9);  // 0.002 % of 200 bar
  // 0.1 %FS per year of 200 bar: 20 kPa / (rho g) / 8766 h = 2.26e-4 m/h.
  EXPECT_NEAR(s.depth.drift_m_per_h, 2e4 / kRhoG / 8766.0, 1e-12);
  ASSERT_TRUE(parseScenario("depth: {resolution_pa: 1.0, grade: quartz}\n", "t.yaml", &s, &error)) << error;
  EXPECT_EQ(s.depth.resolution_pa, 1.0);
  EXPECT_GT(s.depth.drift_m_per_h, 0.0);
  EXPECT_FALSE(parseScenario("depth: {density_error_kgpm3: 80}\n", "t.yaml", &s, &error));
  EXPECT_NE(error.find("depth.density_error_kgpm3"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::sim
