// nav/metrics: errors, smoothness m_A, TUM parsing and association by time.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "nav/metrics/smoothness.h"
#include "nav/metrics/trajectory_association.h"
#include "nav/metrics/trajectory_errors.h"

namespace deepnav {
namespace {

StampedPose pose(double t, const Eigen::Vector3d& p, double yaw) {
  StampedPose s;
  s.t_s = t;
  s.p_robot_in_odom_m = p;
  s.q_odom_robot = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return s;
}

TEST(MetricsErrors, PositionAndGeodesicOrientationErrors) {
  // GIVEN / WHEN / THEN a 3-4-5 offset and a 0.3 rad rotation about a tilted axis
  EXPECT_DOUBLE_EQ(positionError(Eigen::Vector3d(3, 4, 0), Eigen::Vector3d::Zero()), 5.0);
  const Eigen::Quaterniond a(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized()));
  const Eigen::Quaterniond b = a * Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0, 1, 1).normalized()));
  EXPECT_NEAR(orientationError(b, a), 0.3, 1e-12);
  // q and -q are the same rotation
  EXPECT_NEAR(orientationError(Eigen::Quaterniond(-a.coeffs()), a), 0.0, 1e-7);
}

TEST(MetricsErrors, SummaryIsMeanSampleStdRmsMax) {
  const std::vector<double> e = {1.0, 2.0, 3.0, 4.0};
  const ErrorStats s = summarizeErrors(e);
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_NEAR(s.std, std::sqrt(5.0 / 3.0), 1e-12);
  EXPECT_NEAR(s.rms, std::sqrt(7.5), 1e-12);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_EQ(summarizeErrors({}).count, 0u);
}

TEST(MetricsErrors, TrajectoryErrorsPerEpoch) {
  // GIVEN an estimate offset by 0.1 m and 0.05 rad from the truth at every epoch
  std::vector<StampedPose> est, truth;
  for (int k = 0; k < 10; ++k) {
    truth.push_back(pose(k, Eigen::Vector3d(k, 0, 0), 0.1 * k));
    est.push_back(pose(k, Eigen::Vector3d(k, 0.1, 0), 0.1 * k + 0.05));
  }
  // WHEN / THEN
  const TrajectoryErrors t = trajectoryErrors(est, truth);
  ASSERT_EQ(t.position_m.size(), 10u);
  EXPECT_NEAR(t.position.mean, 0.1, 1e-12);
  EXPECT_NEAR(t.position.std, 0.0, 1e-12);
  EXPECT_NEAR(t.orientation.mean, 0.05, 1e-9);
}

TEST(MetricsSmoothness, SmoothIsNearOneJitterIsNearMinusHalf) {
  // GIVEN a smooth curve sampled finely, and white noise positions
  std::vector<Eigen::Vector3d> smooth, jitter;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < 4000; ++k) {
    const double t = 0.01 * k;
    smooth.emplace_back(std::sin(t), std::cos(0.7 * t), 0.1 * t * t);
    jitter.emplace_back(n(rng), n(rng), n(rng));
  }
  // WHEN m_A is computed THEN it is ~1 for the smooth curve and ~-0.5 for jitter (increments of white
  // noise are an MA(1) process with lag-one autocorrelation -1/2)
  const Smoothness s = smoothnessMa(smooth);
  EXPECT_EQ(s.axes_used, 3);
  EXPECT_GT(s.m_a, 0.99);
  const Smoothness j = smoothnessMa(jitter);
  EXPECT_NEAR(j.m_a, -0.5, 0.05);
}

TEST(MetricsSmoothness, ConstantAxesAreLeftOutAndShortInputsGiveNothing) {
  // GIVEN a straight line at constant depth with an alternating (zig-zag) lateral component
  std::vector<Eigen::Vector3d> p;
  for (int k = 0; k < 11; ++k) p.emplace_back(0.5 * k, (k % 2) * 0.1, -10.0);
  // THEN x (constant increments) and z are left out; y alternates: r1 = -1 * (N-1)/N
  const Smoothness s = smoothnessMa(p);
  EXPECT_EQ(s.axes_used, 1);
  EXPECT_NEAR(s.m_a, -0.9, 1e-12);
  EXPECT_EQ(smoothnessMa(std::vector<Eigen::Vector3d>(2, Eigen::Vector3d::Zero())).axes_used, 0);
  double r1 = 0.0;
  const std::vector<double> d = {1.0, 2.0, 3.0, 4.0};
  ASSERT_TRUE(lagOneAutocorrelation(d, &r1));
  EXPECT_NEAR(r1, 0.25, 1e-12);  // (-1.5*-0.5 + -0.5*0.5 + 0.5*1.5) / 5
}

TEST(MetricsSmoothness, AnAxisWithoutMotionDoesNotDragTheScoreDown) {
  // GIVEN a vehicle circling at 0.2 m/s (1.5 m radius) at constant depth, sampled at 100 Hz, whose
  // estimated z holds only 0.1 mm of white noise (the depth corrections)
  std::vector<Eigen::Vector3d> p;
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise_m(0.0, 0.0001);
  const double w_radps = 0.2 / 1.5;
  for (int k = 0; k < 6000; ++k) {
    const double t = 0.01 * k;
    p.emplace_back(1.5 * std::cos(w_radps * t), 1.5 * std::sin(w_radps * t), -100.0 + noise_m(rng));
  }
  // WHEN m_A is computed THEN z alone is jitter (r_z ~ -0.5), which an unweighted mean over the axes
  // would count as a third of the score; pooled by increment variance the score stays that of the motion
  const Smoothness s = smoothnessMa(p);
  EXPECT_EQ(s.axes_used, 3);
  EXPECT_NEAR(s.r_axis.z(), -0.5, 0.05);
  EXPECT_GT(s.r_axis.x(), 0.99);
  EXPECT_LT(s.r_axis.mean(), 0.7);
  EXPECT_GT(s.m_a, 0.95);
  EXPECT_LT(s.m_a, 1.0);
}

TEST(MetricsAssociation, ParsesTumLines) {
  const auto p = parseTumLine("1305031102.175304 1.5 -2 0.25 0 0 0.7071067811865476 0.7071067811865476\r\n");
  ASSERT_TRUE(p.has_value());
  EXPECT_DOUBLE_EQ(p->t_s, 1305031102.175304);
  EXPECT_EQ(p->p_robot_in_odom_m, Eigen::Vector3d(1.5, -2.0, 0.25));
  EXPECT_NEAR(orientationError(p->q_odom_robot, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()))),
              0.0, 1e-9);
  EXPECT_FALSE(parseTumLine("# timestamp tx ty tz qx qy qz qw").has_value());
  EXPECT_FALSE(parseTumLine("   ").has_value());
  EXPECT_FALSE(parseTumLine("1.0 2.0 3.0").has_value());
  EXPECT_FALSE(parseTumLine("1 0 0 0 0 0 0 0").has_value());
  EXPECT_FALSE(parseTumLine("1 nan 0 0 0 0 0 1").has_value());
}

TEST(MetricsAssociation, InterpolatesTruthAtEstimateTimes) {
  // GIVEN ground truth at 10 Hz moving at 1 m/s in x and turning at 1 rad/s, with a gap after 2 s
  std::vector<StampedPose> truth;
  for (int k = 0; k <= 20; ++k) truth.push_back(pose(0.1 * k, Eigen::Vector3d(0.1 * k, 0, 0), 0.1 * k));
  truth.push_back(pose(5.0, Eigen::Vector3d(5, 0, 0), 5.0));
  // AND estimates at odd times, one before the start, one inside the gap, one after the end
  std::vector<StampedPose> est;
  for (double t : {-0.5, 0.05, 0.55, 1.0, 1.99, 3.0, 6.0}) est.push_back(pose(t, Eigen::Vector3d::Zero(), 0.0));
  // WHEN associated with a 0.2 s maximum gap
  const AssociatedTrajectories a = associateByTime(est, truth, 0.2);
  // THEN only the four estimates inside the covered time remain, with exact interpolated truth
  ASSERT_EQ(a.estimate.size(), 4u);
  ASSERT_EQ(a.truth.size(), 4u);
  for (std::size_t i = 0; i < a.truth.size(); ++i) {
    const double t = a.estimate[i].t_s;
    EXPECT_DOUBLE_EQ(a.truth[i].t_s, t);
    EXPECT_NEAR(a.truth[i].p_robot_in_odom_m.x(), t, 1e-12);
    EXPECT_NEAR(orientationError(a.truth[i].q_odom_robot, pose(t, Eigen::Vector3d::Zero(), t).q_odom_robot), 0.0,
                1e-9);
  }
}

}  // namespace
}  // namespace deepnav
