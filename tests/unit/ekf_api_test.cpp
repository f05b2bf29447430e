// The Ekf class as the loop sees it: init errors, alignment, queueing, clones, solution layout.
#include <cmath>
#include <numbers>
#include <string>

#include <Eigen/Cholesky>
#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/ekf.h"
#include "nav/ekf/heading_updater.h"
#include "nav/ekf/imu_to_robot.h"
#include "nav/ekf/initial_alignment.h"

namespace deepnav {
namespace {

ImuSample restingImu(TimeUs t_us, double roll, double pitch) {
  // At rest the accelerometer reads R^T (0, 0, g).
  const Eigen::Matrix3d R = quatFromRollPitchYaw(roll, pitch, 0.3).toRotationMatrix();
  ImuSample s;
  s.t_us = t_us;
  s.f_imu_mps2 = R.transpose() * Eigen::Vector3d(0.0, 0.0, 9.80665);
  return s;
}

TEST(EkfApi, InitRejectsBadConfigNamingTheKey) {
  // GIVEN configs with one bad field each
  Ekf ekf;
  std::string error;
  EkfConfig c;
  c.gyro_arw_radps_rthz = -1.0;
  // WHEN / THEN init fails and names the key
  EXPECT_FALSE(ekf.init(c, &error));
  EXPECT_NE(error.find("gyro_arw_radps_rthz"), std::string::npos);
  c = EkfConfig{};
  c.max_clones = es::kMaxClones + 1;
  EXPECT_FALSE(ekf.init(c, &error));
  EXPECT_NE(error.find("max_clones"), std::string::npos);
  c = EkfConfig{};
  c.q_robot_dvl.coeffs() << 0.0, 0.0, 0.0, 2.0;
  EXPECT_FALSE(ekf.init(c, &error));
  EXPECT_NE(error.find("q_robot_dvl"), std::string::npos);
  c = EkfConfig{};
  c.pos_var_min_m2 = 1.0;
  c.pos_var_max_m2 = 0.5;
  EXPECT_FALSE(ekf.init(c, &error));
  EXPECT_FALSE(ekf.initialised());
  EXPECT_TRUE(ekf.init(EkfConfig{}, &error));
  EXPECT_TRUE(ekf.initialised());
}

TEST(EkfApi, AlignsRollPitchFromGravityYawFromCompassZFromDepth) {
  // GIVEN a robot at rest, rolled 0.05 rad and pitched -0.03 rad, a compass heading and a depth
  EkfConfig c;
  c.magnetic_declination_rad = 0.1;
  c.align_imu_samples = 10;
  Ekf ekf;
  ASSERT_TRUE(ekf.init(c, nullptr));
  HeadingSample h;
  h.t_us = 1000;
  h.heading_rad = 0.5;  // clockwise from magnetic north
  DepthSample d;
  d.t_us = 1000;
  d.depth_m = 12.5;
  // WHEN IMU samples arrive (measurements before alignment are not fused)
  EXPECT_EQ(ekf.fuseHeading(h).status, FuseStatus::kNotAligned);
  EXPECT_EQ(ekf.fuseDepth(d).status, FuseStatus::kNotAligned);
  for (int k = 1; k <= 9; ++k) ekf.setImu(restingImu(k * 10'000, 0.05, -0.03));
  EXPECT_FALSE(ekf.aligned());
  EXPECT_EQ(ekf.solution().stage, NavStage::kInit);
  ekf.setImu(restingImu(100'000, 0.05, -0.03));
  // THEN the state is aligned with ENU yaw = pi/2 - (heading + declination) and z = -depth
  ASSERT_TRUE(ekf.aligned());
  const Eigen::Matrix3d R = ekf.state().x.q_odom_robot.toRotationMatrix();
  EXPECT_NEAR(std::atan2(R(2, 1), R(2, 2)), 0.05, 1e-9);
  EXPECT_NEAR(-std::asin(R(2, 0)), -0.03, 1e-9);
  EXPECT_NEAR(std::atan2(R(1, 0), R(0, 0)), std::numbers::pi / 2.0 - 0.6, 1e-9);
  EXPECT_NEAR(ekf.state().x.p_robot_in_odom_m.z(), -12.5, 1e-12);
  EXPECT_EQ(ekf.state().t_us, 100'000);
  const NavSolution s = ekf.solution();
  EXPECT_EQ(s.stage, NavStage::kWorkspace);
  EXPECT_TRUE(s.status & kStatusAttitudeValid);
}

TEST(EkfApi, SolutionCarriesPoseCovarianceInRosOrder) {
  // GIVEN a reset with a distinct variance on every state
  Ekf ekf;
  ASSERT_TRUE(ekf.init(EkfConfig{}, nullptr));
  EkfInitialState init;
  init.x.p_robot_in_odom_m = Eigen::Vector3d(1.0, 2.0, -3.0);
  init.P.setZero();
  for (int i = 0; i < es::kCoreDim; ++i) init.P(i, i) = 1e-4 * (i + 1);
  init.P(es::kP, es::kTheta + 2) = init.P(es::kTheta + 2, es::kP) = 1e-5;
  ASSERT_TRUE(ekf.reset(5'000'000, init));
  // WHEN the solution is read
  const NavSolution s = ekf.solution();
  // THEN cov_pose is [x y z roll pitch yaw] and cov_v the velocity block
  EXPECT_EQ(s.t_us, 5'000'000);
  EXPECT_EQ(s.p_robot_in_odom_m, init.x.p_robot_in_odom_m);
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(s.cov_pose(i, i), 1e-4 * (es::kP + i + 1));
    EXPECT_DOUBLE_EQ(s.cov_pose(3 + i, 3 + i), 1e-4 * (es::kTheta + i + 1));
    EXPECT_DOUBLE_EQ(s.cov_v_mps2(i, i), 1e-4 * (es::kV + i + 1));
  }
  EXPECT_DOUBLE_EQ(s.cov_pose(0, 5), 1e-5);
  EXPECT_DOUBLE_EQ(s.cov_pose(5, 0), 1e-5);
  EXPECT_TRUE(isFinite(s));
  // AND a non-finite reset is refused
  init.x.v_robot_in_odom_mps.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(ekf.reset(6'000'000, init));
  EXPECT_EQ(ekf.state().t_us, 5'000'000);
}

TEST(EkfApi, StaleFlagsFollowTimeoutsAndZeroMeansUnmonitored) {
  // GIVEN a filter reset at 0 with default timeouts (1 s for DVL, markers unmonitored)
  Ekf ekf;
  ASSERT_TRUE(ekf.init(EkfConfig{}, nullptr));
  ASSERT_TRUE(ekf.reset(0, EkfInitialState{}));
  // WHEN 1.5 s of IMU at rest pass with no aiding
  for (int k = 1; k <= 150; ++k) ekf.setImu(restingImu(k * 10'000, 0.0, 0.0));
  const std::uint32_t f = ekf.solution().faults;
  // THEN DVL, depth, heading, attitude are stale; IMU and markers are not; nothing was rejected
  EXPECT_TRUE(f & staleBit(kSrcDvl));
  EXPECT_TRUE(f & staleBit(kSrcDepth));
  EXPECT_TRUE(f & staleBit(kSrcHeading));
  EXPECT_TRUE(f & staleBit(kSrcAttitude));
  EXPECT_FALSE(f & staleBit(kSrcImu));
  EXPECT_FALSE(f & staleBit(kSrcMarkers));
  EXPECT_FALSE(f & rejectBit(kSrcDvl));
  // AND a depth sample clears its bit and sets the depth status
  DepthSample d;
  d.t_us = 1'500'000;
  d.depth_m = 0.0;
  EXPECT_EQ(ekf.fuseDepth(d).status, FuseStatus::kAccepted);
  EXPECT_FALSE(ekf.solution().faults & staleBit(kSrcDepth));
  EXPECT_TRUE(ekf.solution().status & kStatusDepthValid);
  // AND IMU samples out of order are bad input
  ekf.setImu(restingImu(1'000'000, 0.0, 0.0));
  EXPECT_EQ(ekf.health(kSrcImu).counters.bad_input, 1u);
}

TEST(EkfApi, ClonesAreBoundedAndRelativePoseNeedsAClone) {
  // GIVEN a filter with room for 2 clones
  EkfConfig c;
  c.max_clones = 2;
  Ekf ekf;
  ASSERT_TRUE(ekf.init(c, nullptr));
  ASSERT_TRUE(ekf.reset(0, EkfInitialState{}));
  ekf.setImu(restingImu(10'000, 0.0, 0.0));
  // WHEN three clones are requested at the current time
  EXPECT_EQ(ekf.clonePose(10'000, 1).status, FuseStatus::kAccepted);
  EXPECT_EQ(ekf.clonePose(10'000, 2).status, FuseStatus::kAccepted);
  EXPECT_EQ(ekf.clonePose(10'000, 3).status, FuseStatus::kRejected);
  // THEN the third is refused and counted, the state holds two
  EXPECT_EQ(ekf.state().n_clones, 2);
  EXPECT_EQ(ekf.counters().clone_failures, 1u);
  // AND a relative pose against an unknown clone is rejected, against a known one fused and released
  ekf.setImu(restingImu(20'000, 0.0, 0.0));
  RelativePoseMeasurement rel;
  rel.t_us = 20'000;
  rel.clone_id = 7;
  rel.cov = 1e-4 * Eigen::Matrix<double, 6, 6>::Identity();
  EXPECT_EQ(ekf.fuseRelativePose(rel).status, FuseStatus::kRejected);
  rel.clone_id = 1;
  rel.release_clone = true;
  EXPECT_EQ(ekf.fuseRelativePose(rel).status, FuseStatus::kAccepted);
  EXPECT_EQ(ekf.state().n_clones, 1);
  EXPECT_EQ(ekf.releaseClone(20'000, 2).status, FuseStatus::kAccepted);
  EXPECT_EQ(ekf.state().n_clones, 0);
  EXPECT_TRUE(ekf.solution().status & kStatusPositionValid);
}

TEST(EkfApi, VarianceBoundsHoldDuringLongDeadReckoning) {
  // GIVEN a tight maximum on the velocity variance
  EkfConfig c;
  c.vel_var_max_m2ps2 = 0.04;
  c.accel_vrw_mps2_rthz = 0.5;
  Ekf ekf;
  ASSERT_TRUE(ekf.init(c, nullptr));
  ASSERT_TRUE(ekf.reset(0, EkfInitialState{}));
  // WHEN 60 s pass without aiding
  for (int k = 1; k <= 6000; ++k) ekf.setImu(restingImu(k * 10'000, 0.0, 0.0));
  // THEN the variances stay inside the bounds and P stays symmetric positive definite
  const FilterState& s = ekf.state();
  for (int i = 0; i < 3; ++i) EXPECT_LE(s.P(es::kV + i, es::kV + i), 0.04 * (1 + 1e-12));
  const Eigen::Matrix<double, 15, 15> P = s.P.topLeftCorner<15, 15>();
  EXPECT_TRUE(P.isApprox(P.transpose(), 0.0));
  using Mat15 = Eigen::Matrix<double, 15, 15>;
  EXPECT_EQ(Eigen::LLT<Mat15>(P).info(), Eigen::Success);
}

TEST(EkfApi, ImuMountingAndLeverArmAreCompensated) {
  // GIVEN an IMU turned 90 deg about z, 0.5 m ahead of the robot origin, on a robot level and spinning at
  // 0.4 rad/s about z and speeding up its spin at 0.1 rad/s^2
  const Eigen::Quaterniond q_robot_imu(Eigen::AngleAxisd(std::numbers::pi / 2.0, Eigen::Vector3d::UnitZ()));
  const Eigen::Vector3d r(0.5, 0.0, 0.0), w_prev(0.0, 0.0, 0.399), w(0.0, 0.0, 0.4);
  const Eigen::Vector3d alpha = (w - w_prev) / 0.01;
  // The IMU point sees gravity plus centripetal and tangential acceleration.
  const Eigen::Vector3d f_point_robot = Eigen::Vector3d(0, 0, 9.80665) + alpha.cross(r) + w.cross(w.cross(r));
  ImuSample s;
  s.w_imu_radps = q_robot_imu.conjugate() * w;
  s.f_imu_mps2 = q_robot_imu.conjugate() * f_point_robot;
  // WHEN moved to the robot frame
  const RobotImu u = imuToRobot(s, q_robot_imu, r, w_prev, 0.01);
  // THEN the rate is the robot's and the specific force that of the robot origin (gravity only)
  EXPECT_TRUE(u.w_robot_radps.isApprox(w, 1e-12));
  EXPECT_TRUE(u.f_robot_mps2.isApprox(Eigen::Vector3d(0, 0, 9.80665), 1e-12));
}

TEST(EkfApi, CompassHeadingBecomesEnuYaw) {
  // GIVEN a declination of +0.1 rad (east) and a compass bias of +0.02 rad
  EkfConfig c;
  c.magnetic_declination_rad = 0.1;
  c.heading_bias_rad = 0.02;
  HeadingSample h;
  h.heading_rad = 0.0;  // the compass says north
  // THEN yaw = pi/2 - (heading + declination - bias); a gyrocompass (true north) skips the declination
  EXPECT_NEAR(yawFromHeading(h, c), std::numbers::pi / 2.0 - 0.08, 1e-12);
  h.is_true = true;
  EXPECT_NEAR(yawFromHeading(h, c), std::numbers::pi / 2.0 + 0.02, 1e-12);
  h.heading_rad = std::numbers::pi;  // south: yaw -pi/2 (wrapped)
  h.is_true = true;
  c.heading_bias_rad = 0.0;
  EXPECT_NEAR(yawFromHeading(h, c), -std::numbers::pi / 2.0, 1e-12);
}

}  // namespace
}  // namespace deepnav
