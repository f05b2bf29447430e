// End-to-end bench replay: simulator -> recording -> loop -> recording -> loop, bit for bit.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "board/loop/nav_core.h"
#include "board/replay/bench_replay.h"
#include "board/replay/realtime_replay.h"
#include "tests/support/test_dive.h"
#include "tests/support/source_paths.h"
#include "tests/support/test_replay.h"

namespace deepnav {
namespace {

ReplaySummary replay(const std::string& input, const std::string& out, const std::string& board = "") {
  ReplayOptions o;
  o.input_path = input;
  o.out_dir = out;
  o.board_path = board;
  return testing::replayOrFail(o);
}

class ReplayTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { dive_ = testing::makeTestDive("replay_dive", 15.0); }
  static std::string dive_;
};
std::string ReplayTest::dive_;

TEST_F(ReplayTest, SensorLogRunsTheLoopAtItsRate) {
  // GIVEN a 15 s simulated sensor log WHEN it is replayed THEN the loop ticks at 100 Hz over it, consumes
  // every sensor sample and every stereo pair, and writes trajectory, truth and summary
  const std::string out = ::testing::TempDir() + "replay_a";
  const ReplaySummary s = replay(dive_, out);
  EXPECT_FALSE(s.reproduce);
  EXPECT_NEAR(static_cast<double>(s.ticks), 1500.0, 2.0);
  EXPECT_NEAR(static_cast<double>(s.inputs.imu), 1501.0, 1.0);
  EXPECT_GT(s.inputs.dvl, 70u);
  EXPECT_EQ(s.frames, 151u);
  EXPECT_GT(s.inputs.vision, 140u);
  EXPECT_GT(s.inputs.accepted, 0u);
  EXPECT_TRUE(s.has_truth);
  EXPECT_TRUE(std::filesystem::exists(out + "/trajectory.tum"));
  EXPECT_TRUE(std::filesystem::exists(out + "/truth.tum"));
  EXPECT_TRUE(std::filesystem::exists(out + "/summary.json"));
}

TEST_F(ReplayTest, ReplayOfARecordedRunReproducesEveryOutputBitForBit) {
  // GIVEN the recording of a run WHEN it is replayed THEN every recorded NavSolution is reproduced exactly
  const std::string first = ::testing::TempDir() + "replay_b1";
  const ReplaySummary run = replay(dive_, first);
  const ReplaySummary again = replay(first + "/replay.mcap", ::testing::TempDir() + "replay_b2");
  EXPECT_TRUE(again.reproduce);
  EXPECT_EQ(again.solutions_compared, run.ticks);
  EXPECT_EQ(again.mismatches, 0u);
  EXPECT_EQ(again.inputs.imu, run.inputs.imu);
}

TEST_F(ReplayTest, AnotherBoardMakesTheComparisonFail) {
  // The comparison is real: a different gate changes the outputs, and the replay says so.
  const std::string first = ::testing::TempDir() + "replay_c1";
  replay(dive_, first);
  const std::string board = ::testing::TempDir() + "other_board.yaml";
  std::ofstream(board) << "ekf:\n  gyro_arw_radps_rthz: 2.0e-4\n";
  const ReplaySummary other = replay(first + "/replay.mcap", ::testing::TempDir() + "replay_c2", board);
  EXPECT_GT(other.mismatches, 0u);
}

TEST_F(ReplayTest, RecordingCutOffMidWriteReplaysUpToItsLastCompleteChunk) {
  // GIVEN a recording cut at 60 % of its bytes (as kill -9 leaves it) WHEN replayed THEN the replay runs
  // over its complete chunks, warns, and loses at most about one chunk (1 s) before the cut
  const std::string cut = ::testing::TempDir() + "cut.mcap";
  const auto size = std::filesystem::file_size(dive_);
  std::filesystem::copy_file(dive_, cut, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, size * 6 / 10);
  const ReplaySummary s = replay(cut, ::testing::TempDir() + "replay_cut");
  EXPECT_FALSE(s.warnings.empty());
  EXPECT_GT(s.dive_s, 15.0 * 0.6 - 2.5);
  EXPECT_LT(s.dive_s, 15.0 * 0.6 + 0.5);
}

ReplaySummary replayWith(const std::string& input, const std::string& out, const std::vector<std::string>& overrides) {
  ReplayOptions o;
  o.input_path = input;
  o.out_dir = out;
  o.progress = false;
  o.overrides = overrides;
  ReplaySummary s;
  std::string error;
  EXPECT_TRUE(runBenchReplay(o, &s, &error)) << error;
  return s;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Issue 21: a recording cut at 1 KB replayed with rc 0 and empty outputs. Now an error naming the file.
TEST_F(ReplayTest, RecordingCutWithinItsFirstKilobyteIsAnErrorNamingTheFile) {
  const std::string cut = ::testing::TempDir() + "cut_1k.mcap";
  std::filesystem::copy_file(dive_, cut, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::resize_file(cut, 1024);
  ReplayOptions o;
  o.input_path = cut;
  o.out_dir = ::testing::TempDir() + "replay_cut_1k";
  o.progress = false;
  ReplaySummary s;
  std::string error;
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_NE(error.find(cut + ": holds no data to replay: the file is truncated"), std::string::npos) << error;
  // AND the same through the threaded runtime (--realtime)
  error.clear();
  EXPECT_FALSE(runRealtimeReplay(o, &s, &error));
  EXPECT_NE(error.find(cut + ": no sensor samples to replay"), std::string::npos) << error;
  EXPECT_NE(error.find("cut off after 0 complete chunks"), std::string::npos) << error;
}

// Issue 21: `replay --out ""` wrote its outputs into the root directory. Now refused.
TEST_F(ReplayTest, EmptyOutputDirectoryIsRefused) {
  ReplayOptions o;
  o.input_path = dive_;
  o.out_dir = "";
  o.progress = false;
  ReplaySummary s;
  std::string error;
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_NE(error.find("--out: the output directory is empty"), std::string::npos) << error;
}

// Issue 21: a full disk gave "deepnav replay: " and nothing else. Now the file and the system's reason:
// trajectory.tum goes to /dev/full (every write fails with ENOSPC).
TEST_F(ReplayTest, AFullDiskNamesTheFileAndTheReason) {
  const std::string out = ::testing::TempDir() + "replay_full_disk";
  std::filesystem::create_directories(out);
  std::filesystem::remove(out + "/trajectory.tum");
  std::filesystem::create_symlink("/dev/full", out + "/trajectory.tum");
  ReplayOptions o;
  o.input_path = dive_;
  o.out_dir = out;
  o.progress = false;
  ReplaySummary s;
  std::string error;
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_EQ(error, out + "/trajectory.tum: cannot write: No space left on device");
  std::filesystem::remove(out + "/trajectory.tum");
}

TEST_F(ReplayTest, DeadReckoningRunUsesTheNavigationSensorsOnly) {
  // GIVEN the 15 s dive WHEN replayed as the dead-reckoning run (no VO, no markers)
  const std::string out = ::testing::TempDir() + "replay_dr";
  const ReplaySummary s = replayWith(dive_, out, {"vision.vo_mode=none", "markers.enabled=false"});
  // THEN it ticks through the whole dive in stage 1, no pair goes through the vision worker (nothing it
  // gives could be fused), no marker pose is fused and no panel is ever fixed (that the worker detects no
  // marker with the key off is board_config_test's MarkersEnabledKeySwitchesTheWholeMarkerChain)
  EXPECT_NEAR(static_cast<double>(s.ticks), 1500.0, 2.0);
  EXPECT_EQ(s.frames, 0u);
  EXPECT_EQ(s.frames_not_processed, 151u);
  EXPECT_EQ(s.inputs.vision, 0u);
  EXPECT_EQ(s.markers.observations, 0u);
  EXPECT_EQ(s.modalities.markers.offered, 0u);
  EXPECT_LT(s.panel_fixed_at_s, 0.0);
  EXPECT_LT(s.stage2_at_s, 0.0);
  EXPECT_EQ(s.modalities.vo_orb.offered + s.modalities.vo_planes.offered, 0u);
  // AND the navigation sensors are offered and fused
  EXPECT_EQ(s.modalities.dvl.offered, s.inputs.dvl);
  EXPECT_GT(s.modalities.dvl.fused, s.modalities.dvl.offered / 2);
  EXPECT_GT(s.modalities.depth.fused, 0u);
  EXPECT_GT(s.modalities.compass.fused, 0u);
  // AND it is scored: odom error, ATE, NEES per tick; the panel-relative error is absent (null), not 0
  ASSERT_TRUE(s.has_truth);
  EXPECT_GT(s.metrics.odom.whole.position.count, 1000u);
  EXPECT_FALSE(s.metrics.odom.stage2);
  EXPECT_FALSE(s.metrics.panel);
  EXPECT_GT(s.metrics.nees_position_summary.count, 1000u);
  EXPECT_GT(s.metrics.nees_heading_summary.count, 1000u);
  const std::string json = readText(out + "/summary.json");
  EXPECT_NE(json.find("\"panel_error\": null"), std::string::npos);
  EXPECT_NE(json.find("\"panel_error_absent\": \"the board never fixed the panel\""), std::string::npos);
  EXPECT_NE(json.find("\"nees\": {\"position\": {\"dof\": 3"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(out + "/nees.csv"));
  EXPECT_TRUE(std::filesystem::exists(out + "/truth.tum"));
}

TEST(Replay, MissingOrGarbageFileGivesAClearError) {
  ReplayOptions o;
  o.input_path = "/nonexistent.mcap";
  o.out_dir = ::testing::TempDir() + "replay_err";
  o.progress = false;
  ReplaySummary s;
  std::string error;
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_NE(error.find("/nonexistent.mcap"), std::string::npos) << error;
  const std::string garbage = ::testing::TempDir() + "garbage.mcap";
  std::ofstream(garbage) << "this is not an MCAP file at all, just some text";
  o.input_path = garbage;
  EXPECT_FALSE(runBenchReplay(o, &s, &error));
  EXPECT_NE(error.find(garbage), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav

namespace deepnav {
namespace {

TEST(NavCoreHealth, ASensorThatStopsIsFlaggedStaleAtTheTickEvenWithoutOtherInputs) {
  // GIVEN a loop fed 10 s of a dive WHEN every input stops THEN the ticks alone raise the stale flags
  const std::string dive = testing::makeTestDive("stale_dive", 10.0, 7, /*render=*/false);
  VehicleSetup setup;
  std::string error;
  ASSERT_TRUE(loadVehicleSetup(deepnav::testing::sourceDir() + "/board/sim/board.yaml", &setup, &error)) << error;
  NavCore core;
  ASSERT_TRUE(core.init(setup, nullptr, &error)) << error;
  RecordingReader reader;
  ASSERT_TRUE(reader.open(dive, &error)) << error;
  TimeUs last = 0;
  reader.forEach(true, [&](const ReplayEvent& e) {
    if (e.kind == ReplayEvent::Kind::kInput) {
      core.consume(e.input);
      last = e.t_us;
    }
    return true;
  }, &error);
  EXPECT_EQ(core.tick(last).faults & staleBit(kSrcDvl), 0u);
  const NavSolution later = core.tick(last + 2 * kUsPerS);
  EXPECT_NE(later.faults & staleBit(kSrcDvl), 0u);
  EXPECT_NE(later.faults & staleBit(kSrcImu), 0u);
  EXPECT_NE(later.faults & staleBit(kSrcDepth), 0u);
}

}  // namespace
}  // namespace deepnav
