// The two-stage pipeline end to end on a short rendered dive: stage 1 fixes the panel and builds the
// workspace map, stage 2 fuses the adaptive VO through stochastic clones; the saved workspace lets a
// second run enter stage 2 as soon as the panel is found again, without building a map.
#include <gtest/gtest.h>

#include <filesystem>

#include "board/replay/bench_replay.h"
#include "tests/support/test_dive.h"
#include "tests/support/test_replay.h"

namespace deepnav {
namespace {

// A dive that reaches the panel quickly (short hold and approach) so both stages fit in 40 s, with the
// stage criteria of the board lowered to match.
const std::vector<std::string> kQuickStages = {
    "stage.min_workspace_time_s=5", "stage.min_faces_seen_fraction=0.3", "vision.map_min_frames=6",
    "vision.map_min_voxels=300", "vision.map_every_n_frames=3"};

std::string quickDive() {
  static const std::string path = testing::makeTestDive(
      "stage2", 40.0, 11, true, {{"start_hold_s: 4.0", "start_hold_s: 1.0"}, {"approach_s: 26.0", "approach_s: 8.0"}});
  return path;
}

ReplaySummary replay(const std::string& out, const std::vector<std::string>& extra, const std::string& ws_in,
                     const std::string& ws_out) {
  ReplayOptions o;
  o.input_path = quickDive();
  o.out_dir = testing::tempPath("stage2_" + out);
  o.overrides = kQuickStages;
  o.overrides.insert(o.overrides.end(), extra.begin(), extra.end());
  o.workspace_in = ws_in;
  o.workspace_out = ws_out;
  return testing::replayOrFail(o);
}

TEST(Stage2Replay, AdaptiveVoIsFusedAndTheWorkspaceRestartsInStage2) {
  const std::string ws = testing::tempPath("stage2_ws");
  // GIVEN a dive replayed through both stages (EKF-adaptive), saving its workspace
  const ReplaySummary first = replay("first", {}, "", ws);
  // THEN the panel is fixed, the map built, stage 2 entered after both, and VO results fused
  ASSERT_GE(first.panel_fixed_at_s, 0.0);
  ASSERT_GE(first.stage2_at_s, first.panel_fixed_at_s);
  EXPECT_GE(first.map_frames, 6);
  EXPECT_GT(first.vo.accepted, 20u);
  EXPECT_GT(first.vo.clones, 0u);
  EXPECT_LT(first.errors.position.mean, 0.15);
  EXPECT_LT(first.errors.orientation.mean * 180.0 / M_PI, 1.5);
  ASSERT_TRUE(std::filesystem::exists(ws + "/workspace.bt"));
  ASSERT_TRUE(std::filesystem::exists(ws + "/workspace.yaml"));
  // AND every stage-2 pair chose a modality; no VO before stage 2
  int stage2_pairs = 0;
  for (const FrameStat& f : first.frame_stats) {
    if (f.stage != 2) {
      EXPECT_FALSE(f.orb_vo || f.planes_vo) << f.t_s;
      continue;
    }
    ++stage2_pairs;
    EXPECT_NE(f.selected, 0) << f.t_s;
  }
  EXPECT_GT(stage2_pairs, 50);

  // WHEN the same dive starts from the saved workspace with the stage-1 time criterion out of reach
  const ReplaySummary second = replay("second", {"stage.min_workspace_time_s=1000"}, ws, "");
  // THEN stage 2 comes as soon as the markers fix the panel again, on the restored map
  EXPECT_TRUE(second.workspace_restored);
  ASSERT_GE(second.stage2_at_s, 0.0);
  EXPECT_LE(second.stage2_at_s, second.panel_fixed_at_s + 0.05);
  EXPECT_EQ(second.map_frames, 0);  // nothing inserted: the map came from the file
  EXPECT_GT(second.vo.accepted, 20u);
  EXPECT_LT(second.errors.position.mean, 0.15);

  // WHEN stage 2 runs without marker poses (the paper's T_L3)
  const ReplaySummary tl3 = replay("tl3", {"stage.fuse_markers_in_stage2=false"}, "", "");
  // THEN VO carries stage 2 and the error stays bounded (issue figures: 0.25 m, 2 deg)
  ASSERT_GE(tl3.stage2_at_s, 0.0);
  EXPECT_LT(tl3.markers.fused, first.markers.fused);
  EXPECT_GT(tl3.vo.accepted, 20u);
  EXPECT_LT(tl3.errors.position.mean, 0.25);
  EXPECT_LT(tl3.errors.orientation.mean * 180.0 / M_PI, 2.0);
}

TEST(Stage2Replay, BadOverrideNamesTheKey) {
  ReplayOptions o;
  o.input_path = testing::makeTestDive("stage2_bad", 2.0, 3, false);
  o.out_dir = testing::tempPath("stage2_bad");
  o.progress = false;
  o.overrides = {"vision.vo_mode=fastest"};
  ReplaySummary s;
  std::string error;
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_NE(error.find("vision.vo_mode"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav
