// The stage machine of the two-stage method: init -> workspace (stage 1) -> optimised (stage 2).
#include "nav/stage/stage_machine.h"

#include <gtest/gtest.h>

#include <string>

namespace deepnav {
namespace {

constexpr TimeUs kS = kUsPerS;

StageMachine makeMachine(double min_time_s = 30.0, double min_faces = 0.5) {
  StageMachine m;
  StageConfig c;
  c.min_workspace_time_s = min_time_s;
  c.min_faces_seen_fraction = min_faces;
  std::string error;
  EXPECT_TRUE(m.init(c, &error)) << error;
  return m;
}

StageInputs aligned() {
  StageInputs in;
  in.filter_aligned = true;
  return in;
}

StageInputs ready(double faces = 1.0) {
  StageInputs in = aligned();
  in.panel_fixed = true;
  in.map_ready = true;
  in.faces_seen_fraction = faces;
  return in;
}

TEST(StageMachine, StaysInInitUntilTheFilterIsAligned) {
  // GIVEN a fresh machine and a filter not yet aligned
  StageMachine m = makeMachine();
  EXPECT_EQ(m.stage(), NavStage::kInit);
  // WHEN updated, even with everything else ready THEN it stays in kInit
  StageInputs in = ready();
  in.filter_aligned = false;
  EXPECT_EQ(m.update(0, in), NavStage::kInit);
  EXPECT_EQ(m.update(10 * kS, in), NavStage::kInit);
  // WHEN the filter aligns THEN stage 1
  EXPECT_EQ(m.update(11 * kS, aligned()), NavStage::kWorkspace);
  EXPECT_EQ(m.stageEnteredUs(), 11 * kS);
  EXPECT_EQ(m.transitions(), 1u);
}

TEST(StageMachine, StageTwoNeedsPanelMapTimeAndFaces) {
  StageMachine m = makeMachine(30.0, 0.5);
  ASSERT_EQ(m.update(0, aligned()), NavStage::kWorkspace);
  // GIVEN the panel fixed and the map ready at 10 s, but only 10 s spent in stage 1
  EXPECT_EQ(m.update(10 * kS, ready()), NavStage::kWorkspace);
  EXPECT_EQ(m.workspaceTimeUs(), 10 * kS);
  // WHEN 30 s have passed but only a third of the faces was seen THEN still stage 1
  EXPECT_EQ(m.update(30 * kS, ready(1.0 / 3.0)), NavStage::kWorkspace);
  // WHEN the map is not ready THEN still stage 1
  StageInputs no_map = ready();
  no_map.map_ready = false;
  EXPECT_EQ(m.update(31 * kS, no_map), NavStage::kWorkspace);
  // WHEN the panel is not fixed THEN still stage 1
  StageInputs no_panel = ready();
  no_panel.panel_fixed = false;
  EXPECT_EQ(m.update(32 * kS, no_panel), NavStage::kWorkspace);
  // WHEN everything holds THEN stage 2, entered at that time
  EXPECT_EQ(m.update(33 * kS, ready(2.0 / 3.0)), NavStage::kOptimised);
  EXPECT_EQ(m.stageEnteredUs(), 33 * kS);
  EXPECT_EQ(m.transitions(), 2u);
  // AND it stays there while the panel and map stay good, whatever the faces fraction does
  EXPECT_EQ(m.update(40 * kS, ready(0.0)), NavStage::kOptimised);
}

TEST(StageMachine, MinimumTimeIsExactToTheMicrosecond) {
  StageMachine m = makeMachine(30.0, 0.0);
  m.update(1 * kS, aligned());
  EXPECT_EQ(m.update(31 * kS - 1, ready()), NavStage::kWorkspace);
  EXPECT_EQ(m.update(31 * kS, ready()), NavStage::kOptimised);
}

TEST(StageMachine, FallsBackWhenPanelOrMapIsLostAndToInitWhenAlignmentIs) {
  StageMachine m = makeMachine(0.0, 0.0);
  m.update(0, aligned());
  ASSERT_EQ(m.update(1, ready()), NavStage::kOptimised);
  // GIVEN stage 2 WHEN the caller resets the panel THEN stage 1, with the stage-1 clock restarted
  StageInputs no_panel = ready();
  no_panel.panel_fixed = false;
  EXPECT_EQ(m.update(2 * kS, no_panel), NavStage::kWorkspace);
  EXPECT_EQ(m.workspaceTimeUs(), 0);
  ASSERT_EQ(m.update(3 * kS, ready()), NavStage::kOptimised);
  // WHEN the map is invalidated THEN stage 1
  StageInputs no_map = ready();
  no_map.map_ready = false;
  EXPECT_EQ(m.update(4 * kS, no_map), NavStage::kWorkspace);
  // WHEN the filter loses alignment (reset) from any stage THEN kInit
  EXPECT_EQ(m.update(5 * kS, StageInputs{}), NavStage::kInit);
  ASSERT_EQ(m.update(6 * kS, ready()), NavStage::kWorkspace);
  ASSERT_EQ(m.update(7 * kS, ready()), NavStage::kOptimised);
  StageInputs lost = ready();
  lost.filter_aligned = false;
  EXPECT_EQ(m.update(8 * kS, lost), NavStage::kInit);
}

TEST(StageMachine, StageOneTimeSurvivesAnAlignmentLoss) {
  // GIVEN 20 s in stage 1, then 100 s without alignment, then 10 s more in stage 1 (30 s needed)
  StageMachine m = makeMachine(30.0, 0.0);
  m.update(0, aligned());
  m.update(20 * kS, aligned());
  EXPECT_EQ(m.update(20 * kS, StageInputs{}), NavStage::kInit);
  m.update(120 * kS, StageInputs{});
  EXPECT_EQ(m.update(120 * kS, aligned()), NavStage::kWorkspace);
  EXPECT_EQ(m.workspaceTimeUs(), 20 * kS);
  // THEN stage 2 comes after the 30th second in stage 1, not counting the time in kInit
  EXPECT_EQ(m.update(129 * kS, ready()), NavStage::kWorkspace);
  EXPECT_EQ(m.update(130 * kS, ready()), NavStage::kOptimised);
}

TEST(StageMachine, RestartWithASavedWorkspaceGoesStraightToStageTwo) {
  // GIVEN a restart with the panel pose and map loaded from a saved workspace
  StageMachine m = makeMachine(30.0, 0.5);
  StageInputs restored = ready(0.0);
  restored.workspace_restored = true;
  restored.filter_aligned = false;
  EXPECT_EQ(m.update(0, restored), NavStage::kInit);
  // WHEN the filter aligns THEN stage 2 at once: this run's stage-1 criteria do not apply
  restored.filter_aligned = true;
  EXPECT_EQ(m.update(1 * kS, restored), NavStage::kOptimised);
  EXPECT_EQ(m.transitions(), 1u);
  // AND a restored panel whose map is still loading waits in stage 1 only until the map is ready
  StageMachine m2 = makeMachine(30.0, 0.5);
  StageInputs loading = restored;
  loading.map_ready = false;
  EXPECT_EQ(m2.update(0, loading), NavStage::kWorkspace);
  EXPECT_EQ(m2.update(1 * kS, restored), NavStage::kOptimised);
}

TEST(StageMachine, TimeRunningBackwardsCountsAsNoTime) {
  StageMachine m = makeMachine(10.0, 0.0);
  m.update(100 * kS, aligned());
  m.update(105 * kS, aligned());
  // GIVEN an update stamped before the last one THEN no time is added, and the next counts from 105
  // s
  m.update(50 * kS, aligned());
  EXPECT_EQ(m.workspaceTimeUs(), 5 * kS);
  m.update(108 * kS, aligned());
  EXPECT_EQ(m.workspaceTimeUs(), 8 * kS);
}

TEST(StageMachine, DeterministicAndResettable) {
  // GIVEN two machines fed the same sequence THEN the same stages; reset() returns to kInit
  StageMachine a = makeMachine(), b = makeMachine();
  for (int i = 0; i < 100; ++i) {
    StageInputs in = i < 5 ? StageInputs{} : (i < 40 ? aligned() : ready(0.7));
    EXPECT_EQ(a.update(i * kS, in), b.update(i * kS, in)) << i;
  }
  EXPECT_EQ(a.stage(), NavStage::kOptimised);
  a.reset();
  EXPECT_EQ(a.stage(), NavStage::kInit);
  EXPECT_EQ(a.workspaceTimeUs(), 0);
  EXPECT_EQ(a.transitions(), 0u);
}

TEST(StageMachine, ConfigValidationNamesTheKey) {
  StageMachine m;
  std::string error;
  StageConfig c;
  c.min_workspace_time_s = -1.0;
  EXPECT_FALSE(m.init(c, &error));
  EXPECT_NE(error.find("min_workspace_time_s"), std::string::npos);
  c = StageConfig{};
  c.min_faces_seen_fraction = 1.5;
  EXPECT_FALSE(m.init(c, &error));
  EXPECT_NE(error.find("min_faces_seen_fraction"), std::string::npos);
}

}  // namespace
}  // namespace deepnav
