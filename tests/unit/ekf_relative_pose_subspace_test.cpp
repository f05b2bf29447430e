// A relative pose that constrains only part of the 6 DoF (plane VO of degenerate plane sets): the updater
// keeps the constrained directions of its covariance (relative_pose_updater.h), with a Jacobian that
// matches central differences of the projected residual.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/initial_alignment.h"
#include "nav/ekf/relative_pose_updater.h"
#include "nav/ekf/stochastic_clone.h"

namespace deepnav {
namespace {

constexpr double kEps = 1e-6;

FilterState stateWithClone(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  FilterState s;
  s.x.p_robot_in_odom_m = Eigen::Vector3d(n(rng), n(rng), -10.0 + n(rng));
  s.x.q_odom_robot = quatFromRollPitchYaw(0.3 * n(rng), 0.3 * n(rng), 2.0 * n(rng));
  EXPECT_EQ(augmentClone(5, es::kMaxClones, &s), CloneStatus::kOk);
  PoseClone& c = s.clones[static_cast<std::size_t>(s.n_clones - 1)];
  c.p_robot_in_odom_m = s.x.p_robot_in_odom_m + Eigen::Vector3d(0.2, -0.1, 0.05);
  c.q_odom_robot = expSo3Quat(Eigen::Vector3d(0.02, -0.03, 0.1)) * s.x.q_odom_robot;
  const int dim = s.dim();
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(dim, dim);
  s.P.topLeftCorner(dim, dim) = A * A.transpose() + Eigen::MatrixXd::Identity(dim, dim);
  return s;
}

// One plane seen from the robot (normal along robot x): the translation along x and the rotation about
// y and z are measured; the rest holds the plane registration's unobservable variance (1e4).
RelativePoseMeasurement onePlaneMeasurement() {
  RelativePoseMeasurement m;
  m.clone_id = 5;
  m.q_robota_robotb = quatFromRollPitchYaw(0.01, 0.02, -0.03);
  m.p_robotb_in_robota_m = Eigen::Vector3d(0.1, -0.2, 0.05);
  m.cov.setZero();
  m.cov.diagonal() << 1e-4, 1e4, 1e4, 1e4, 2e-5, 3e-5;
  m.cov(4, 5) = m.cov(5, 4) = 1e-5;
  return m;
}

TEST(EkfRelativePoseSubspace, ConstrainedBasisKeepsTheSmallVariances) {
  // GIVEN a covariance with three measured and three unmeasured directions, mixed by a rotation
  const RelativePoseMeasurement m = onePlaneMeasurement();
  Eigen::Matrix<double, 6, 6> Q = Eigen::Matrix<double, 6, 6>::Identity();
  Q.topLeftCorner<3, 3>() = quatFromRollPitchYaw(0.3, -0.2, 0.9).toRotationMatrix();
  const MeasMatrix cov = Q * m.cov * Q.transpose();
  // WHEN its constrained basis is taken
  MeasMatrix U;
  MeasVector var;
  const int k = relativePoseConstrainedBasis(cov, &U, &var);
  // THEN it spans the three measured directions (the rotated x, and the y-z rotation block), orthonormal
  ASSERT_EQ(k, 3);
  EXPECT_TRUE((U.transpose() * U).isApprox(Eigen::Matrix3d::Identity(), 1e-9));
  const Eigen::Vector3d x_rot = Q.col(0).head<3>();
  Eigen::Matrix<double, 6, 1> e_x = Eigen::Matrix<double, 6, 1>::Zero();
  e_x.head<3>() = x_rot;
  EXPECT_NEAR((U * U.transpose() * e_x).norm(), 1.0, 1e-9);
  for (int i : {4, 5}) EXPECT_NEAR((U * U.transpose()).col(i)(i), 1.0, 1e-9);
  EXPECT_LT(var.maxCoeff(), kRelativePoseUnconstrainedVariance);
  EXPECT_NEAR(var.sum(), 1e-4 + 2e-5 + 3e-5, 1e-10);  // eigen-solver error ~ eps * 1e4
}

TEST(EkfRelativePoseSubspace, ProjectedMeasurementHasOnlyConstrainedRowsAndMatchesNumericJacobian) {
  // GIVEN a state with a clone and a one-plane relative pose (3 of 6 directions measured)
  std::mt19937_64 rng(3);
  const FilterState s = stateWithClone(rng);
  const RelativePoseMeasurement m = onePlaneMeasurement();
  // WHEN it is linearised
  Linearization lin;
  ASSERT_TRUE(linearizeRelativePose(s, m, &lin));
  // THEN three rows remain, their noise the measured variances, and no row sees the unmeasured ones
  ASSERT_EQ(lin.m, 3);
  EXPECT_TRUE(lin.R.isDiagonal(1e-15));
  EXPECT_LT(lin.R.maxCoeff(), kRelativePoseUnconstrainedVariance);
  // AND the Jacobian equals central differences of the projected residual (the basis is fixed by the
  // covariance, so the same rows are kept at every perturbed state)
  const int n = s.dim();
  for (int j = 0; j < n; ++j) {
    ErrorVector dx = ErrorVector::Zero(n);
    dx(j) = kEps;
    FilterState plus = s, minus = s;
    injectErrorState(dx, &plus);
    injectErrorState(-dx, &minus);
    Linearization lp, lm;
    ASSERT_TRUE(linearizeRelativePose(plus, m, &lp));
    ASSERT_TRUE(linearizeRelativePose(minus, m, &lm));
    for (int i = 0; i < lin.m; ++i) {
      EXPECT_NEAR(lin.H(i, j), -(lp.residual(i) - lm.residual(i)) / (2.0 * kEps), 1e-6) << i << "," << j;
    }
  }
}

TEST(EkfRelativePoseSubspace, UnmeasuredDirectionsDoNotEnterTheResidual) {
  // GIVEN the one-plane measurement and the same one moved by 0.5 m along y (unmeasured)
  std::mt19937_64 rng(4);
  const FilterState s = stateWithClone(rng);
  const RelativePoseMeasurement m = onePlaneMeasurement();
  RelativePoseMeasurement moved = m;
  moved.p_robotb_in_robota_m.y() += 0.5;
  // WHEN both are linearised
  Linearization a, b;
  ASSERT_TRUE(linearizeRelativePose(s, m, &a));
  ASSERT_TRUE(linearizeRelativePose(s, moved, &b));
  // THEN the residuals agree (the translation rows measure x only)
  ASSERT_EQ(a.m, b.m);
  for (int i = 0; i < a.m; ++i) EXPECT_NEAR(a.residual(i), b.residual(i), 1e-12);
  // AND 1 cm along x (measured) moves the residual by 1 cm
  moved.p_robotb_in_robota_m.x() += 0.01;
  ASSERT_TRUE(linearizeRelativePose(s, moved, &b));
  EXPECT_NEAR((a.residual - b.residual).norm(), 0.01, 1e-9);
}

TEST(EkfRelativePoseSubspace, FullyMeasuredPoseIsUnchanged) {
  // GIVEN an ordinary 6-DoF relative pose (all variances small)
  std::mt19937_64 rng(5);
  const FilterState s = stateWithClone(rng);
  RelativePoseMeasurement m = onePlaneMeasurement();
  m.cov.diagonal() << 1e-4, 2e-4, 3e-4, 1e-5, 2e-5, 3e-5;
  // WHEN it is linearised
  Linearization lin;
  ASSERT_TRUE(linearizeRelativePose(s, m, &lin));
  // THEN it keeps its six rows, in order, with its own covariance
  ASSERT_EQ(lin.m, 6);
  EXPECT_TRUE(lin.R.isApprox(m.cov, 0.0));
}

TEST(EkfRelativePoseSubspace, NothingMeasuredIsRefused) {
  std::mt19937_64 rng(6);
  const FilterState s = stateWithClone(rng);
  RelativePoseMeasurement m = onePlaneMeasurement();
  m.cov = Eigen::Matrix<double, 6, 6>::Identity() * 1e4;
  Linearization lin;
  EXPECT_FALSE(linearizeRelativePose(s, m, &lin));
}

}  // namespace
}  // namespace deepnav
