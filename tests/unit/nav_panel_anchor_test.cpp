// nav/pipeline/panel_anchor: the fixed panel held in the EKF as a clone of the robot pose at the fix.
// Markers fused against the clone keep the panel's error in odom in the covariance (the robot is not
// pinned to millimetres in odom), a compass update turns the panel with the robot (the panel-relative
// pose is kept), and a filter reset that drops the clone is survived.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/ekf.h"
#include "nav/pipeline/panel_anchor.h"

namespace deepnav {
namespace {

constexpr double kG = 9.80665;

// An aligned filter at rest at the origin, yaw 0.4 rad, with position 1-sigma 0.5 m and yaw 3 deg.
void startAtRest(Ekf* ekf) {
  ASSERT_TRUE(ekf->init(EkfConfig{}, nullptr));
  EkfInitialState s;
  s.x.q_odom_robot = Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));
  s.P.diagonal().head<15>().setConstant(1e-8);
  s.P.diagonal().segment<3>(es::kP).setConstant(0.25);
  s.P.diagonal().segment<3>(es::kV).setConstant(1e-4);
  s.P(es::kTheta + 2, es::kTheta + 2) = std::pow(3.0 * std::numbers::pi / 180.0, 2);
  ASSERT_TRUE(ekf->reset(0, s));
}

void restingImuUntil(Ekf* ekf, TimeUs t_end_us) {
  for (TimeUs t = ekf->state().t_us + 10'000; t <= t_end_us; t += 10'000) {
    ImuSample u;
    u.t_us = t;
    u.f_imu_mps2 = Eigen::Vector3d(0.0, 0.0, kG);
    ekf->setImu(u);
  }
}

Eigen::Isometry3d panelPose() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(1.5, 0.8, -0.5);
  return T;
}

// A marker-like relative pose against the anchor: the robot has not moved since the fix.
RelativePoseMeasurement stillRelativeToAnchor(TimeUs t_us, std::uint32_t id) {
  RelativePoseMeasurement m;
  m.t_us = t_us;
  m.clone_id = id;
  m.cov = Eigen::Matrix<double, 6, 6>::Identity() * 1e-6;  // 1 mm, 1 mrad
  m.source = kSrcMarkers;
  return m;
}

// A filter at rest for 1 s, then the panel anchored at panelPose() against a clone of that instant.
void anchorAtOneSecond(Ekf* ekf, PanelAnchor* anchor) {
  startAtRest(ekf);
  restingImuUntil(ekf, 1'000'000);
  anchor->anchor(1'000'000, panelPose(), ekf);
}

double yawOf(const Eigen::Matrix3d& R) { return std::atan2(R(1, 0), R(0, 0)); }

TEST(PanelAnchor, MarkersAgainstTheCloneKeepThePanelsOdomErrorInTheCovariance) {
  // GIVEN a filter with 0.5 m of position uncertainty, anchored at 1 s
  Ekf ekf;
  PanelAnchor anchor;
  anchorAtOneSecond(&ekf, &anchor);
  ASSERT_TRUE(anchor.ready(ekf));
  EXPECT_TRUE(anchor.T_odom_panel(ekf).isApprox(panelPose(), 1e-12));
  // WHEN 100 millimetre-grade marker poses relative to the anchor are fused over 10 s
  for (int k = 1; k <= 100; ++k) {
    const TimeUs t = 1'000'000 + k * 100'000;
    restingImuUntil(&ekf, t);
    EXPECT_EQ(ekf.fuseRelativePose(stillRelativeToAnchor(t, anchor.cloneId())).status, FuseStatus::kAccepted);
  }
  ASSERT_TRUE(anchor.ready(ekf));
  // THEN the robot's position in odom keeps (almost) its 0.5 m sigma, the part markers cannot see
  const Eigen::Matrix3d P_pos = ekf.state().P.block<3, 3>(es::kP, es::kP);
  EXPECT_GT(std::sqrt(P_pos(0, 0)), 0.45);
  EXPECT_GT(std::sqrt(P_pos(1, 1)), 0.45);
  // AND the robot relative to the anchor is known to millimetres: var(p - p_anchor) is small
  const int c = es::cloneOffset(0);
  const Eigen::Matrix3d P_rel = P_pos + ekf.state().P.block<3, 3>(c, c) - ekf.state().P.block<3, 3>(es::kP, c) -
                                ekf.state().P.block<3, 3>(c, es::kP);
  EXPECT_LT(std::sqrt(P_rel.diagonal().maxCoeff()), 0.003);
}

TEST(PanelAnchor, ACompassUpdateTurnsThePanelWithTheRobot) {
  // GIVEN an anchored panel and markers holding the robot relative to it
  Ekf ekf;
  PanelAnchor anchor;
  anchorAtOneSecond(&ekf, &anchor);
  for (int k = 1; k <= 20; ++k) {
    const TimeUs t = 1'000'000 + k * 100'000;
    restingImuUntil(&ekf, t);
    ekf.fuseRelativePose(stillRelativeToAnchor(t, anchor.cloneId()));
  }
  ASSERT_TRUE(anchor.ready(ekf));
  const Eigen::Isometry3d T_odom_robot0 = [&] {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = ekf.state().x.q_odom_robot.toRotationMatrix();
    T.translation() = ekf.state().x.p_robot_in_odom_m;
    return T;
  }();
  const double yaw_panel_robot0 = yawOf((anchor.T_odom_panel(ekf).inverse() * T_odom_robot0).linear());
  // WHEN a compass heading 2 deg away from the estimate (1-sigma 0.5 deg) is fused
  const TimeUs t = 3'000'000 + 10'000;
  restingImuUntil(&ekf, t);
  HeadingSample h;
  h.t_us = t;
  h.is_true = true;
  h.heading_rad = std::numbers::pi / 2.0 - (0.4 + 2.0 * std::numbers::pi / 180.0);
  h.sigma_rad = 0.5 * std::numbers::pi / 180.0;
  ASSERT_EQ(ekf.fuseHeading(h).status, FuseStatus::kAccepted);
  // THEN the robot turns by most of the 2 deg in odom, the panel with it: the panel-relative yaw stays
  const Eigen::Matrix3d R = ekf.state().x.q_odom_robot.toRotationMatrix();
  EXPECT_GT(yawOf(R) - 0.4, 1.5 * std::numbers::pi / 180.0);
  const double yaw_odom_panel = yawOf(anchor.T_odom_panel(ekf).linear());
  EXPECT_GT(yaw_odom_panel - 2.0, 1.5 * std::numbers::pi / 180.0);
  const double yaw_panel_robot = yawOf(anchor.T_odom_panel(ekf).linear().transpose() * R);
  EXPECT_LT(std::abs(yaw_panel_robot - yaw_panel_robot0), 0.05 * std::numbers::pi / 180.0);
}

TEST(PanelAnchor, AResetThatDropsTheCloneIsSurvivedWithTheLastPanelPose) {
  // GIVEN an anchored panel
  Ekf ekf;
  PanelAnchor anchor;
  anchorAtOneSecond(&ekf, &anchor);
  ASSERT_TRUE(anchor.ready(ekf));
  const std::uint32_t first_id = anchor.cloneId();
  // WHEN the filter is reset (every clone dropped)
  EkfInitialState s;
  s.x = ekf.state().x;
  ASSERT_TRUE(ekf.reset(1'500'000, s));
  // THEN the anchor reports the loss, keeps the panel where it was, and re-anchors under a new id
  EXPECT_FALSE(anchor.ready(ekf));
  EXPECT_EQ(anchor.counters().losses, 1u);
  EXPECT_FALSE(anchor.anchored());
  EXPECT_TRUE(anchor.T_odom_panel(ekf).isApprox(panelPose(), 1e-9));
  restingImuUntil(&ekf, 2'000'000);
  anchor.anchor(2'000'000, anchor.T_odom_panel(ekf), &ekf);
  EXPECT_TRUE(anchor.ready(ekf));
  EXPECT_NE(anchor.cloneId(), first_id);
  EXPECT_TRUE(anchor.T_odom_panel(ekf).isApprox(panelPose(), 1e-9));
}

}  // namespace
}  // namespace deepnav
