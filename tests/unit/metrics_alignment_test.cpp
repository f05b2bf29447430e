// nav/metrics: SE(3) alignment (aligned ATE) and the relative pose error per metre travelled.
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "nav/metrics/relative_pose_error.h"
#include "nav/metrics/trajectory_alignment.h"

namespace deepnav {
namespace {

StampedPose pose(double t, const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
  StampedPose s;
  s.t_s = t;
  s.p_robot_in_odom_m = p;
  s.q_odom_robot = q;
  return s;
}

StampedPose transformed(const Eigen::Isometry3d& T, const StampedPose& p) {
  return pose(p.t_s, T * p.p_robot_in_odom_m, Eigen::Quaterniond(T.linear()) * p.q_odom_robot);
}

Eigen::Isometry3d someRigidTransform() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = Eigen::Vector3d(1.0, -2.0, 0.5);
  return T;
}

// Truth on the corners of a 2 m square (repeated), each pose yawing; the estimate is the truth with the
// z offsets +d, -d, +d, -d at the corners (1, 1), (1, -1), (-1, -1), (-1, 1) and rotation errors of
// +/- r about the robot's x axis, then moved by an arbitrary rigid transform.
// sum_i x_i s_i = sum_i y_i s_i = 0 for those signs, so the offsets leave the cross-covariance and hence
// the optimal alignment unchanged: after it the position error is d at every pose and the rotation
// error r, exactly.
struct SquareCase {
  std::vector<StampedPose> truth, estimate;
};
SquareCase squareCase(double d, double r) {
  const double corners[4][2] = {{1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
  const double signs[4] = {1, -1, 1, -1};
  const Eigen::Isometry3d T = someRigidTransform();
  SquareCase c;
  for (int k = 0; k < 12; ++k) {
    const int i = k % 4;
    const Eigen::Vector3d p(corners[i][0], corners[i][1], 1.5);
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3 * k, Eigen::Vector3d::UnitZ()));
    c.truth.push_back(pose(0.1 * k, p, q));
    const Eigen::Quaterniond dq(Eigen::AngleAxisd(signs[i] * r, Eigen::Vector3d::UnitX()));
    c.estimate.push_back(transformed(T.inverse(), pose(0.1 * k, p + Eigen::Vector3d(0, 0, signs[i] * d), q * dq)));
  }
  return c;
}

TEST(MetricsAlignment, RecoversAKnownRigidTransform) {
  // GIVEN an estimate that is the truth moved by T^-1 WHEN aligned THEN T comes back and the ATE is zero
  const SquareCase c = squareCase(0.0, 0.0);
  const AlignedTrajectoryErrors a = alignedTrajectoryErrors(c.estimate, c.truth);
  EXPECT_TRUE(a.T_align.isApprox(someRigidTransform(), 1e-9));
  EXPECT_LT(a.errors.position.rms, 1e-9);
  EXPECT_LT(a.errors.orientation.rms, 1e-7);
}

TEST(MetricsAlignment, AlignedErrorsOfAHandComputedCase) {
  // GIVEN the square case with d = 0.05 m and r = 0.02 rad WHEN aligned THEN the alignment is still T,
  // the position RMSE 0.05 m and the rotation RMSE 0.02 rad (every pose the same), while the unaligned
  // errors are dominated by T
  const SquareCase c = squareCase(0.05, 0.02);
  const AlignedTrajectoryErrors a = alignedTrajectoryErrors(c.estimate, c.truth);
  EXPECT_TRUE(a.T_align.isApprox(someRigidTransform(), 1e-9));
  EXPECT_NEAR(a.errors.position.rms, 0.05, 1e-9);
  EXPECT_NEAR(a.errors.position.max, 0.05, 1e-9);
  EXPECT_NEAR(a.errors.orientation.rms, 0.02, 1e-9);
  EXPECT_EQ(a.errors.position.count, 12u);
  EXPECT_GT(trajectoryErrors(c.estimate, c.truth).position.rms, 1.0);
}

TEST(MetricsAlignment, DegenerateInputsGiveTheIdentity) {
  const std::vector<StampedPose> two = {pose(0, Eigen::Vector3d(1, 0, 0), Eigen::Quaterniond::Identity()),
                                        pose(1, Eigen::Vector3d(2, 0, 0), Eigen::Quaterniond::Identity())};
  EXPECT_TRUE(alignRigid(two, two).isApprox(Eigen::Isometry3d::Identity()));
  const std::vector<StampedPose> same(5, pose(0, Eigen::Vector3d(1, 2, 3), Eigen::Quaterniond::Identity()));
  EXPECT_TRUE(alignRigid(same, same).isApprox(Eigen::Isometry3d::Identity()));
}

// Truth: 10 m straight along x in steps of 0.25 m (exact in binary, so every 1 m segment is 4 steps).
// Estimate: positions scaled by 1.02 (a 2 % scale error, e.g. of the DVL) and a roll error growing by
// 0.01 rad per metre (about the direction of travel, so it does not turn the translation).
struct LineCase {
  std::vector<StampedPose> truth, estimate;
};
LineCase lineCase() {
  LineCase c;
  for (int k = 0; k <= 40; ++k) {
    const double x = 0.25 * k;
    c.truth.push_back(pose(0.25 * k, Eigen::Vector3d(x, 0, -100), Eigen::Quaterniond::Identity()));
    c.estimate.push_back(pose(0.25 * k, Eigen::Vector3d(1.02 * x, 0, -100),
                              Eigen::Quaterniond(Eigen::AngleAxisd(0.01 * x, Eigen::Vector3d::UnitX()))));
  }
  return c;
}

TEST(MetricsRpe, DriftPerMetreOfAHandComputedCase) {
  // GIVEN the line case WHEN the RPE over 1 m is computed THEN 10 segments, each 0.02 m off (2 % of the
  // distance) and 0.01 rad (0.573 deg/m) turned
  const LineCase c = lineCase();
  const RelativePoseErrors r = relativePoseErrors(c.estimate, c.truth, 1.0);
  ASSERT_EQ(r.length_m.size(), 10u);
  EXPECT_DOUBLE_EQ(r.length_m[3], 1.0);
  EXPECT_NEAR(r.translation.rms, 0.02, 1e-12);
  EXPECT_NEAR(r.translation_percent.mean, 2.0, 1e-9);
  EXPECT_NEAR(r.translation_percent.max, 2.0, 1e-9);
  EXPECT_NEAR(r.rotation.rms, 0.01, 1e-12);
  EXPECT_NEAR(r.rotation_rad_per_m.mean * 180.0 / std::numbers::pi, 0.5729578, 1e-6);
  // 2 m segments: 5 of them, 0.04 m and 0.02 rad each, the same drift per metre
  const RelativePoseErrors r2 = relativePoseErrors(c.estimate, c.truth, 2.0);
  ASSERT_EQ(r2.length_m.size(), 5u);
  EXPECT_NEAR(r2.translation.rms, 0.04, 1e-12);
  EXPECT_NEAR(r2.translation_percent.mean, 2.0, 1e-9);
  EXPECT_NEAR(r2.rotation_rad_per_m.mean, 0.01, 1e-12);
}

TEST(MetricsRpe, InvariantToARigidTransformOfTheEstimate) {
  LineCase c = lineCase();
  const RelativePoseErrors before = relativePoseErrors(c.estimate, c.truth, 1.0);
  for (StampedPose& p : c.estimate) p = transformed(someRigidTransform(), p);
  const RelativePoseErrors after = relativePoseErrors(c.estimate, c.truth, 1.0);
  ASSERT_EQ(after.length_m.size(), before.length_m.size());
  EXPECT_NEAR(after.translation.rms, before.translation.rms, 1e-12);
  EXPECT_NEAR(after.rotation.rms, before.rotation.rms, 1e-12);
}

TEST(MetricsRpe, StandingStillGivesNoSegment) {
  // A robot that does not travel a metre has no segment (not a zero error)
  std::vector<StampedPose> still;
  for (int k = 0; k < 100; ++k) {
    still.push_back(pose(0.01 * k, Eigen::Vector3d(0, 0, 0.001 * k), Eigen::Quaterniond::Identity()));
  }
  EXPECT_TRUE(relativePoseErrors(still, still, 1.0).length_m.empty());
}

}  // namespace
}  // namespace deepnav
