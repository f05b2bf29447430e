// The covariance guard: symmetry, variance bounds that keep P positive semi-definite, and the checks that
// make the filter reset instead of emitting a non-finite value.
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include "nav/ekf/covariance_guard.h"
#include "nav/ekf/ekf_config.h"
#include "nav/ekf/filter_state.h"
#include "nav/ekf/stochastic_clone.h"

namespace deepnav {
namespace {

FilterState stateWithRandomCovariance(int clones) {
  FilterState s;
  for (int i = 0; i < clones; ++i) augmentClone(static_cast<std::uint32_t>(i), es::kMaxClones, &s);
  const int n = s.dim();
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n) * 0.1;
  s.P.topLeftCorner(n, n) = A * A.transpose() + 1e-3 * Eigen::MatrixXd::Identity(n, n);
  return s;
}

TEST(EkfCovariance, BoundsClampVariancesAndKeepPsd) {
  // GIVEN a PD covariance with one velocity variance above the max and one angle variance below the min
  EkfConfig c;
  c.vel_var_max_m2ps2 = 1e-3;
  c.angle_var_min_rad2 = 0.5;
  FilterState s = stateWithRandomCovariance(2);
  s.P(es::kV, es::kV) = 5.0;
  s.P(es::kTheta, es::kTheta) = 1e-6;
  s.P(3, 20) += 1e-9;  // a little asymmetry
  // WHEN conditioned
  ASSERT_TRUE(conditionCovariance(varianceBoundsFrom(c), &s));
  // THEN the variances are at the bounds, P is symmetric and still positive semi-definite
  const int n = s.dim();
  const Eigen::MatrixXd P = s.P.topLeftCorner(n, n);
  EXPECT_DOUBLE_EQ(P(es::kV, es::kV), 1e-3);
  EXPECT_DOUBLE_EQ(P(es::kTheta, es::kTheta), 0.5);
  EXPECT_TRUE(P.isApprox(P.transpose(), 0.0));
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(P).eigenvalues().minCoeff(), 0.0);
}

TEST(EkfCovariance, NonFiniteOrNonPositiveDiagonalIsReportedForReset) {
  // GIVEN covariances broken in different ways
  const VarianceBounds b = varianceBoundsFrom(EkfConfig{});
  FilterState s = stateWithRandomCovariance(1);
  s.P(4, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(conditionCovariance(b, &s));
  s = stateWithRandomCovariance(1);
  s.P(17, 17) = -1e-3;
  EXPECT_FALSE(conditionCovariance(b, &s));
  // AND a NaN off the diagonal, or in the nominal state, is caught by the finite check
  s = stateWithRandomCovariance(1);
  EXPECT_TRUE(isFiniteState(s));
  s.P(2, 18) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(isFiniteState(s));
  s = stateWithRandomCovariance(1);
  s.clones[0].p_robot_in_odom_m.y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(isFiniteState(s));
  // WHEN the covariance is reset THEN it is the configured diagonal, without clones
  resetCovariance(EkfConfig{}, &s);
  EXPECT_EQ(s.n_clones, 0);
  EXPECT_DOUBLE_EQ(s.P(es::kTheta + 2, es::kTheta + 2), 0.1 * 0.1);
  EXPECT_TRUE(conditionCovariance(b, &s));
}

}  // namespace
}  // namespace deepnav
