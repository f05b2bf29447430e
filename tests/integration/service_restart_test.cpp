// Crash safety of `deepnav run`: killed with SIGKILL after entering stage 2, its recording stays readable up
// to its last chunk and replays bit for bit; restarted, it reloads the workspace it saved to
// `service.state_dir` (map + T_panel_map) and resumes in stage 2 as soon as the markers fix the panel
// again, without a new stage-1 map.
#include <gtest/gtest.h>

#include <filesystem>
#include <thread>

#include "board/replay/bench_replay.h"
#include "drivers/replay/recording_reader.h"
#include "tests/support/service_fixture.h"
#include "tests/support/test_dive.h"

namespace deepnav {
namespace {

// The quick two-stage dive of stage2_replay_test: the panel is reached early and the stage criteria are
// lowered to match, so stage 1 ends within a few seconds of the panel being fixed.
std::map<std::string, std::string> quickStages(const std::string& state_dir) {
  return {{"stage.min_workspace_time_s", "5"}, {"stage.min_faces_seen_fraction", "0.3"},
          {"vision.map_min_frames", "6"},      {"vision.map_min_voxels", "300"},
          {"vision.map_every_n_frames", "3"},  {"service.state_dir", state_dir}};
}

struct RunTimeline {
  double panel_fixed_s = -1, stage2_s = -1;  // recording time since the first solution
  int max_map_frames = 0;                    // clouds inserted into a map of this run
  std::uint64_t solutions = 0;
};

RunTimeline readTimeline(const std::string& recording) {
  RunTimeline r;
  RecordingReader reader;
  std::string error;
  EXPECT_TRUE(reader.open(recording, &error)) << error;
  TimeUs first = -1;
  reader.forEach(
      true,
      [&](const ReplayEvent& e) {
        const auto* vision = e.kind == ReplayEvent::Kind::kInput ? std::get_if<VisionResult>(&e.input) : nullptr;
        if (vision) r.max_map_frames = std::max(r.max_map_frames, vision->map_frames);
        if (e.kind != ReplayEvent::Kind::kSolution) return true;
        if (first < 0) first = e.t_us;
        ++r.solutions;
        const double t = usToS(e.t_us - first);
        if ((e.solution.status & kStatusPanelFixed) && r.panel_fixed_s < 0) r.panel_fixed_s = t;
        if (e.solution.stage == NavStage::kOptimised && r.stage2_s < 0) r.stage2_s = t;
        return true;
      },
      &error);
  return r;
}

TEST(ServiceRestart, KilledInStage2ResumesInStage2FromTheSavedWorkspace) {
  const std::string dive = testing::makeTestDive(
      "restart", 20.0, 11, true, {{"start_hold_s: 4.0", "start_hold_s: 1.0"}, {"approach_s: 26.0", "approach_s: 8.0"}});
  const std::string state = testing::tempPath("restart_state");
  std::filesystem::remove_all(state);

  // GIVEN `deepnav run` recording a dive, with a state directory
  const std::string board1 = testing::makeServiceBoard("restart_board1", dive, quickStages(state));
  const std::string rec1 = testing::tempPath("restart_run1.mcap");
  testing::DeepnavProcess run1({"run", "--board", board1, "--record", rec1});
  // WHEN it enters stage 2 (the workspace appears in the state directory) and is then killed with SIGKILL
  const auto t1 = std::chrono::steady_clock::now();
  while (!std::filesystem::exists(state + "/workspace/workspace.yaml") && testing::secondsSince(t1) < 90.0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_TRUE(std::filesystem::exists(state + "/workspace/workspace.bt")) << run1.stderrText();
  const double saved_after_s = testing::secondsSince(t1);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // it keeps recording in stage 2 a while
  run1.signal(SIGKILL);
  EXPECT_EQ(run1.wait(5.0), -1);  // died by the signal
  EXPECT_NE(run1.stderrText().find("workspace saved to"), std::string::npos) << run1.stderrText();

  // THEN its recording opens, says it was cut off, holds stage 2, and replays bit for bit
  RecordingReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(rec1, &error)) << error;
  EXPECT_TRUE(reader.truncated());
  const RunTimeline first = readTimeline(rec1);
  EXPECT_GE(first.stage2_s, 0.0);
  EXPECT_GE(first.max_map_frames, 6);
  ReplayOptions o;
  o.input_path = rec1;
  o.out_dir = testing::tempPath("restart_replay1");
  o.progress = false;
  ReplaySummary s;
  ASSERT_TRUE(runBenchReplay(o, &s, &error)) << error;
  EXPECT_TRUE(s.reproduce);
  EXPECT_GT(s.solutions_compared, 500u);
  EXPECT_EQ(s.mismatches, 0u);

  // WHEN it is restarted with the stage-1 time criterion out of reach (a new map could not end stage 1)
  std::map<std::string, std::string> settings = quickStages(state);
  settings["stage.min_workspace_time_s"] = "1000";
  const std::string board2 = testing::makeServiceBoard("restart_board2", dive, settings);
  const std::string rec2 = testing::tempPath("restart_run2.mcap");
  testing::NotifyReceiver systemd;
  const auto t2 = std::chrono::steady_clock::now();
  testing::DeepnavProcess run2({"run", "--board", board2, "--record", rec2}, {{"NOTIFY_SOCKET", systemd.path()}});
  const auto messages = systemd.receive(60.0, "stage 2 optimised");
  const double restart_to_stage2_s = testing::secondsSince(t2);
  ASSERT_FALSE(messages.empty());
  ASSERT_NE(messages.back().text.find("stage 2 optimised"), std::string::npos) << run2.stderrText();
  run2.signal(SIGTERM);
  EXPECT_EQ(run2.wait(5.0), 0) << run2.stderrText();
  EXPECT_NE(run2.stderrText().find("workspace restored from"), std::string::npos) << run2.stderrText();

  // THEN it reached stage 2 on the restored map, at the tick the panel was fixed again, inserting no cloud
  const RunTimeline second = readTimeline(rec2);
  ASSERT_GE(second.panel_fixed_s, 0.0);
  ASSERT_GE(second.stage2_s, 0.0);
  EXPECT_LE(second.stage2_s, second.panel_fixed_s + 0.05);
  EXPECT_EQ(second.max_map_frames, 0);
  // AND its recording says it started from the saved workspace, and replays bit for bit
  ReplayOptions o2 = o;
  o2.input_path = rec2;
  o2.out_dir = testing::tempPath("restart_replay2");
  ReplaySummary s2;
  ASSERT_TRUE(runBenchReplay(o2, &s2, &error)) << error;
  EXPECT_TRUE(s2.reproduce);
  EXPECT_TRUE(s2.workspace_restored);
  EXPECT_GT(s2.solutions_compared, 500u);
  EXPECT_EQ(s2.mismatches, 0u);
  std::printf("run 1: workspace saved %.1f s after start (stage 2 at %.1f s of the dive); restart: stage 2 %.1f s "
              "after the start (panel fixed at %.1f s of the dive, stage 2 at %.1f s)\n",
              saved_after_s, first.stage2_s, restart_to_stage2_s, second.panel_fixed_s, second.stage2_s);
}

TEST(ServiceRestart, UnwritableStateDirFailsTheStartNamingTheKey) {
  const std::string dive = testing::makeTestDive("restart_bad", 2.0, 3, false);
  const std::string board = testing::makeServiceBoard("restart_bad_board", dive, {{"service.state_dir", "/proc/deepnav"}});
  testing::DeepnavProcess run({"run", "--board", board, "--no-record"});
  EXPECT_EQ(run.wait(20.0), 2);
  EXPECT_NE(run.stderrText().find("service.state_dir"), std::string::npos) << run.stderrText();
}

}  // namespace
}  // namespace deepnav
