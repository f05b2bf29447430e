// Compass errors the board does not know: the deviation series against heading (a simulated compass
// swing recovers the configured coefficients), the steel panel's magnetic field against distance, and the
// per-dive residual bias; plus the compass grades in the loader.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "sim_test_stats.h"
#include "tools/sim/rotation.h"
#include "tools/sim/scenario_loader.h"
#include "tools/sim/sensors/compass_model.h"

namespace deepnav::sim {
namespace {

using test::mean;
using test::restingState;
using test::stddev;
constexpr double kPi = std::numbers::pi;
constexpr double kRadToDeg = 180.0 / kPi;

KinematicState at(const Eigen::Vector3d& p_m, double yaw_rad) {
  KinematicState s = test::restingStateYawed(yaw_rad);
  s.p_robot_in_odom_m = p_m;
  return s;
}

// Least-squares fit of A + B sin psi + C cos psi + D sin 2psi + E cos 2psi (degrees).
CompassDeviation fitDeviation(const std::vector<double>& psi_rad, const std::vector<double>& delta_deg) {
  Eigen::MatrixXd H(psi_rad.size(), 5);
  Eigen::VectorXd y(psi_rad.size());
  for (std::size_t i = 0; i < psi_rad.size(); ++i) {
    const double p = psi_rad[i];
    H.row(i) << 1.0, std::sin(p), std::cos(p), std::sin(2.0 * p), std::cos(2.0 * p);
    y(i) = delta_deg[i];
  }
  const Eigen::VectorXd x = H.colPivHouseholderQr().solve(y);
  return {x(0), x(1), x(2), x(3), x(4)};
}

TEST(SimCompassDeviation, SwingRecoversTheOneAndTwoCycleCoefficients) {
  CompassConfig c;  // noise 0.3 deg, bias 2 deg: the board knows the bias, not the deviation
  c.declination_deg = 5.0;
  c.deviation = {0.5, 3.0, -2.0, 1.0, -0.7};
  CompassModel compass;
  std::string error;
  ASSERT_TRUE(compass.init(c, PanelGeometry{}, 0.0, 3, &error)) << error;
  // A swing: 10 turns, one reading every 0.1 deg of heading (N = 36000).
  std::vector<double> psi_rad, delta_deg;
  for (int k = 0; k < 36000; ++k) {
    const double yaw_rad = 2.0 * kPi * k / 3600.0;
    const double magnetic_rad = wrapTo2Pi(kPi / 2.0 - yaw_rad - 5.0 * kDegToRad);
    const HeadingSample h = compass.measure(at(Eigen::Vector3d(0.0, 0.0, 1.5), yaw_rad), k);
    psi_rad.push_back(magnetic_rad);
    delta_deg.push_back(wrapToPi(h.heading_rad - magnetic_rad - 2.0 * kDegToRad) * kRadToDeg);
  }
  const CompassDeviation fit = fitDeviation(psi_rad, delta_deg);
  // White noise 0.3 deg over N = 36000 evenly spread headings: sigma(A) = 0.3 / sqrt(N) = 0.0016 deg,
  // sigma(B..E) = 0.3 sqrt(2 / N) = 0.0022 deg. 0.01 deg is more than 4 sigma.
  EXPECT_NEAR(fit.a_deg, 0.5, 0.01);
  EXPECT_NEAR(fit.b_deg, 3.0, 0.01);
  EXPECT_NEAR(fit.c_deg, -2.0, 0.01);
  EXPECT_NEAR(fit.d_deg, 1.0, 0.01);
  EXPECT_NEAR(fit.e_deg, -0.7, 0.01);
  std::vector<double> residual_deg;
  for (std::size_t i = 0; i < psi_rad.size(); ++i) residual_deg.push_back(delta_deg[i] - fit.at_deg(psi_rad[i]));
  EXPECT_NEAR(stddev(residual_deg) / 0.3, 1.0, 0.02);  // what is left is the white noise (2 % >> 0.4 % sd)
}

// The default panel (front face's normal along +x = east) with a remanent moment along that normal and
// a moment induced by the Earth's field: the example of tools/sim/README.md.
CompassConfig panelCompass() {
  CompassConfig c;
  c.noise_deg = 0.0;
  c.bias_deg = 0.0;
  c.panel_magnet.permanent_moment_am2 = {150.0, 0.0, 0.0};
  c.panel_magnet.induced_moment_am2_per_ut = 5.0;
  return c;
}

TEST(SimCompassPanelField, HeadingErrorAgainstDistanceToThePanel) {
  CompassModel compass;
  std::string error;
  ASSERT_TRUE(compass.init(panelCompass(), PanelGeometry{}, 0.0, 1, &error)) << error;
  // In front of the front face (x = 1 m), at the dipole's height (0.75 m above the seabed), facing it.
  auto errorAt_deg = [&](double distance_m) {
    return compass.panelHeadingError_rad(at(Eigen::Vector3d(1.0 + distance_m, 0.0, 0.75), kPi)) * kRadToDeg;
  };
  EXPECT_GT(std::abs(errorAt_deg(1.0)), 5.0);
  EXPECT_GT(std::abs(errorAt_deg(2.0)), 2.0);
  for (double d = 5.0; d <= 50.0; d += 0.5) ASSERT_LT(std::abs(errorAt_deg(d)), 0.5) << d;
  // Far away the error is the small-field limit -B_east / H of the dipole's field (horizontal moment
  // m_x = 150 A m^2 along the line joining: B_east = 2 m_x mu0 / (4 pi r^3)): decays as 1/r^3.
  for (double r : {10.0, 20.0}) {
    const double b_east_ut = 2.0 * 150.0 * 1e-7 * 1e6 / (r * r * r);
    EXPECT_NEAR(errorAt_deg(r - 1.0) / (-b_east_ut / 20.0 * kRadToDeg), 1.0, 0.01) << r;
  }
  const double slope = std::log(std::abs(errorAt_deg(19.0) / errorAt_deg(9.0))) / std::log(20.0 / 10.0);
  EXPECT_NEAR(slope, -3.0, 0.02);
  std::printf("[compass] panel heading error at 1, 1.5, 2, 3, 5 m from the front face: %.2f %.2f %.2f %.2f %.2f deg\n",
              errorAt_deg(1.0), errorAt_deg(1.5), errorAt_deg(2.0), errorAt_deg(3.0), errorAt_deg(5.0));
}

TEST(SimCompassPanelField, ReadingFollowsTheVectorSumOfTheFields) {
  CompassModel compass;
  std::string error;
  ASSERT_TRUE(compass.init(panelCompass(), PanelGeometry{}, 0.0, 1, &error)) << error;
  // The reading is the heading of the disturbed horizontal field: check against the field itself.
  PanelMagneticField field;
  const EarthField earth{20.0, 40.0, 0.0};
  field.init(panelCompass().panel_magnet, PanelGeometry{}, 0.0, earth);
  for (double yaw_deg : {0.0, 37.0, 200.0}) {
    const Eigen::Vector3d p(1.8, -1.3, 1.5);
    const Eigen::Vector3d b = earth.inOdom_ut() + field.field_ut(p);
    const double expected_rad = wrapTo2Pi(kPi / 2.0 - yaw_deg * kDegToRad - std::atan2(b.x(), b.y()));
    EXPECT_NEAR(wrapToPi(compass.noiselessHeading_rad(at(p, yaw_deg * kDegToRad)) - expected_rad), 0.0, 1e-12);
  }
  // Off: the same reading as without any panel.
  CompassConfig off = panelCompass();
  off.panel_magnet = PanelMagnetConfig{};
  ASSERT_TRUE(compass.init(off, PanelGeometry{}, 0.0, 1, &error));
  EXPECT_NEAR(compass.noiselessHeading_rad(at(Eigen::Vector3d(1.8, 0.0, 0.75), 0.0)), kPi / 2.0, 1e-15);
}

TEST(SimCompassResidualBias, DrawnPerDiveWithTheConfiguredMeanAndSigma) {
  CompassConfig c;
  c.residual_bias_deg = 1.5;
  c.residual_bias_sigma_deg = 0.8;
  std::vector<double> draws_deg;
  std::string error;
  for (std::uint64_t seed = 1; seed <= 4000; ++seed) {
    CompassModel compass;
    ASSERT_TRUE(compass.init(c, PanelGeometry{}, 0.0, seed, &error));
    draws_deg.push_back(compass.residualBias_rad() * kRadToDeg);
  }
  // 4000 dives: sd of the mean 0.8 / sqrt(4000) = 0.013 deg, of the sd about 0.8 / sqrt(8000) = 0.009 deg.
  EXPECT_NEAR(mean(draws_deg), 1.5, 0.05);
  EXPECT_NEAR(stddev(draws_deg), 0.8, 0.04);
}

TEST(SimCompassResidualBias, WithinADiveTheMeanErrorIsTheResidualAndTheNoiseIsUnchanged) {
  CompassConfig with;
  with.residual_bias_deg = -1.2;
  with.residual_bias_sigma_deg = 0.5;
  CompassModel biased, plain;
  std::string error;
  ASSERT_TRUE(biased.init(with, PanelGeometry{}, 0.0, 21, &error));
  ASSERT_TRUE(plain.init(CompassConfig{}, PanelGeometry{}, 0.0, 21, &error));
  std::vector<double> diff_deg, err_deg;
  const KinematicState s = at(Eigen::Vector3d(0.0, 0.0, 1.5), 0.3);
  for (int k = 0; k < 20000; ++k) {
    const double b = biased.measure(s, k).heading_rad, p = plain.measure(s, k).heading_rad;
    diff_deg.push_back(wrapToPi(b - p) * kRadToDeg);
    err_deg.push_back(wrapToPi(b - (kPi / 2.0 - 0.3 + 2.0 * kDegToRad)) * kRadToDeg);
  }
  const double residual_deg = biased.residualBias_rad() * kRadToDeg;
  for (double d : diff_deg) ASSERT_NEAR(d, residual_deg, 1e-9);  // same noise draws, shifted
  EXPECT_NEAR(mean(err_deg), residual_deg, 0.3 / std::sqrt(20000.0) * 4.0);
}

TEST(SimCompassGrades, GradeSetsItsFiguresAndExplicitKeysOverride) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario("compass:\n  noise_deg: 0.7\n  grade: fluxgate\n", "t.yaml", &s, &error)) << error;
  EXPECT_EQ(s.compass.grade, CompassGrade::kFluxgate);
  EXPECT_EQ(s.compass.noise_deg, 0.7);                // the key, although written before the grade
  EXPECT_EQ(s.compass.residual_bias_sigma_deg, 0.3);  // the grade's
  ASSERT_TRUE(parseScenario("compass: {grade: gyrocompass}\n", "t.yaml", &s, &error)) << error;
  EXPECT_TRUE(s.compass.true_north);
  EXPECT_FALSE(parseScenario("compass: {grade: gyrocompass, deviation_b_deg: 2.0}\n", "t.yaml", &s, &error));
  EXPECT_NE(error.find("compass.true_north"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("compass: {grade: flux}\n", "t.yaml", &s, &error));
  EXPECT_NE(error.find("compass.grade"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("compass: {earth_horizontal_field_ut: 200}\n", "t.yaml", &s, &error));
  EXPECT_NE(error.find("uT"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::sim
