// board/replay/replay_metrics: the panel-relative error, stage-2 subsets, NEES per tick, the true panel
// pose from the simulator's metadata.
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "board/replay/replay_metrics.h"

namespace deepnav {
namespace {

Eigen::Isometry3d truePanel() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(3.0, -4.0, -1000.0);
  return T;
}

// 20 s at 10 Hz circling; the estimate is the truth shifted by `offset` (a drift the navigation sensors
// cannot see); the board's panel estimate, fixed from t = 5 s, carries the same shift when `common`
// (the panel was measured from the drifted pose), else is exact. Stage 2 from t = 10 s.
struct Case {
  std::vector<StampedPose> estimate, truth;
  std::vector<ReplayTick> ticks;
};
Case makeCase(const Eigen::Vector3d& offset, bool common, bool panel_fixed = true) {
  Case c;
  for (int k = 0; k <= 200; ++k) {
    const double t = 0.1 * k;
    StampedPose p;
    p.t_s = t;
    p.p_robot_in_odom_m = Eigen::Vector3d(3.0 + 2.0 * std::cos(0.2 * t), -4.0 + 2.0 * std::sin(0.2 * t), -998.5);
    p.q_odom_robot = Eigen::Quaterniond(Eigen::AngleAxisd(0.2 * t + M_PI, Eigen::Vector3d::UnitZ()));
    c.truth.push_back(p);
    StampedPose e = p;
    e.p_robot_in_odom_m += offset;
    c.estimate.push_back(e);
    ReplayTick r;
    r.stage = t >= 10.0 ? NavStage::kOptimised : NavStage::kWorkspace;
    r.panel_fixed = panel_fixed && t >= 5.0;
    r.T_odom_panel = truePanel();
    if (common) r.T_odom_panel.translation() += offset;
    r.filter_t_s = t;
    r.p_filter_m = e.p_robot_in_odom_m;
    r.q_filter = e.q_odom_robot;
    r.P_position_m2 = Eigen::Matrix3d::Identity() * (offset.squaredNorm() / 3.0);  // NEES 3 every tick
    r.var_yaw_rad2 = 1e-4;
    c.ticks.push_back(r);
  }
  return c;
}

TEST(MetricsReplay, ACommonShiftIsAnOdomErrorButNoPanelRelativeError) {
  // GIVEN an estimate 0.3 m off in the odom frame and a panel estimated from it (off by the same)
  const Case c = makeCase(Eigen::Vector3d(0.3, 0.0, 0.0), true);
  const ReplayMetrics m = computeMetrics(c.estimate, c.ticks, c.truth, truePanel());
  // THEN the odom error is 0.3 m everywhere, the panel-relative error zero (over the 151 ticks with a
  // panel, 101 of them in stage 2), and the aligned ATE zero (a pure translation)
  EXPECT_NEAR(m.odom.whole.position.mean, 0.3, 1e-12);
  EXPECT_EQ(m.odom.whole.position.count, 201u);
  ASSERT_TRUE(m.odom.stage2);
  EXPECT_EQ(m.odom.stage2->position.count, 101u);
  ASSERT_TRUE(m.panel);
  EXPECT_EQ(m.panel->whole.position.count, 151u);
  EXPECT_LT(m.panel->whole.position.max, 1e-9);
  EXPECT_LT(m.panel->whole.orientation.max, 1e-7);
  ASSERT_TRUE(m.panel->stage2);
  EXPECT_EQ(m.panel->stage2->position.count, 101u);
  EXPECT_LT(m.ate.errors.position.rms, 1e-9);
  EXPECT_EQ(m.panel_estimate.size(), 151u);
  // NEES: e = 0.3 m against P = 0.03 I: 0.09 / 0.03 = 3 at every tick; heading error 0
  EXPECT_EQ(m.nees_position.size(), 201u);
  EXPECT_NEAR(m.nees_position_summary.mean, 3.0, 1e-9);
  EXPECT_NEAR(m.nees_heading_summary.mean, 0.0, 1e-9);
}

TEST(MetricsReplay, TheStage2WindowIsItsFirstSixtySeconds) {
  // GIVEN 100 s at 10 Hz, stage 2 from t = 10 s, an exact panel, and an estimate exact until t = 70 s
  // then 1 m off
  std::vector<StampedPose> estimate, truth;
  std::vector<ReplayTick> ticks;
  for (int k = 0; k < 1000; ++k) {
    StampedPose p;
    p.t_s = 0.1 * k;
    p.p_robot_in_odom_m = Eigen::Vector3d(0.01 * k, 0.0, -998.5);
    truth.push_back(p);
    StampedPose e = p;
    if (p.t_s >= 70.0 - 1e-9) e.p_robot_in_odom_m.y() += 1.0;
    estimate.push_back(e);
    ReplayTick r;
    r.stage = p.t_s >= 10.0 - 1e-9 ? NavStage::kOptimised : NavStage::kWorkspace;
    r.panel_fixed = true;
    r.T_odom_panel = truePanel();
    r.filter_t_s = p.t_s;
    ticks.push_back(r);
  }
  const ReplayMetrics m = computeMetrics(estimate, ticks, truth, truePanel());
  // THEN the window holds the 600 ticks of 10 s <= t < 70 s, all exact, in both frames; stage 2 as a whole
  // has the 300 ticks 1 m off among its 900
  ASSERT_TRUE(m.panel && m.panel->stage2_window && m.odom.stage2_window);
  EXPECT_EQ(m.panel->stage2_window->position.count, 600u);
  EXPECT_LT(m.panel->stage2_window->position.max, 1e-9);
  EXPECT_EQ(m.odom.stage2_window->position.count, 600u);
  EXPECT_NEAR(m.panel->stage2->position.mean, 300.0 / 900.0, 1e-9);
}

TEST(MetricsReplay, AnExactPanelTurnsTheRobotErrorIntoAPanelRelativeError) {
  // GIVEN the same drifted robot but the true panel pose on the board THEN the panel-relative position
  // error is the 0.3 m (rotations do not change its size)
  const Case c = makeCase(Eigen::Vector3d(0.0, 0.3, 0.0), false);
  const ReplayMetrics m = computeMetrics(c.estimate, c.ticks, c.truth, truePanel());
  ASSERT_TRUE(m.panel);
  EXPECT_NEAR(m.panel->whole.position.mean, 0.3, 1e-9);
  EXPECT_NEAR(m.panel->whole.position.max, 0.3, 1e-9);
}

TEST(MetricsReplay, WithoutAPanelEstimateOrTruthThePanelErrorIsAbsentNotZero) {
  const Case never = makeCase(Eigen::Vector3d(0.3, 0, 0), true, false);
  const ReplayMetrics a = computeMetrics(never.estimate, never.ticks, never.truth, truePanel());
  EXPECT_FALSE(a.panel);
  EXPECT_NE(a.panel_absent_reason.find("never fixed"), std::string::npos);
  EXPECT_NEAR(a.odom.whole.position.mean, 0.3, 1e-12);
  const Case fixed = makeCase(Eigen::Vector3d(0.3, 0, 0), true);
  const ReplayMetrics b = computeMetrics(fixed.estimate, fixed.ticks, fixed.truth, std::nullopt);
  EXPECT_FALSE(b.panel);
  EXPECT_NE(b.panel_absent_reason.find("no true panel pose"), std::string::npos);
}

TEST(MetricsReplay, TruePanelFromTheSimulatorsMetadata) {
  // GIVEN the record deepnav-sim writes THEN the pose comes back; without panel keys: none, silently
  const std::map<std::string, std::string> sim = {
      {"scenario", "x.yaml"}, {"seed", "3"}, {"p_panel_in_odom_m", "3 -4 -1000"}, {"yaw_odom_panel_deg", "90"}};
  std::string error;
  const auto T = truthPanelFromMetadata(&sim, &error);
  ASSERT_TRUE(T) << error;
  EXPECT_TRUE(T->isApprox(truePanel(), 1e-12));
  const std::map<std::string, std::string> old = {{"scenario", "x.yaml"}, {"seed", "3"}};
  error.clear();
  EXPECT_FALSE(truthPanelFromMetadata(&old, &error));
  EXPECT_TRUE(error.empty());
  EXPECT_FALSE(truthPanelFromMetadata(nullptr, &error));
  // a quaternion instead of the yaw; a malformed position is reported
  const std::map<std::string, std::string> quat = {{"p_panel_in_odom_m", "3 -4 -1000"},
                                                   {"q_odom_panel_xyzw", "0 0 0.7071067811865476 0.7071067811865476"}};
  const auto Tq = truthPanelFromMetadata(&quat, &error);
  ASSERT_TRUE(Tq);
  EXPECT_TRUE(Tq->isApprox(truePanel(), 1e-12));
  const std::map<std::string, std::string> bad = {{"p_panel_in_odom_m", "3 -4"}, {"yaw_odom_panel_deg", "90"}};
  EXPECT_FALSE(truthPanelFromMetadata(&bad, &error));
  EXPECT_NE(error.find("p_panel_in_odom_m"), std::string::npos);
}

}  // namespace
}  // namespace deepnav
