// A vision stage that throws during a replay (issue 21: OpenCV's StereoSGBM asserting on its range aborted
// `deepnav replay` and `deepnav run` 0.2-0.7 s in) costs the pairs it threw on, not the run: the replay
// goes to the end, every tick is there, the failed pairs are counted in the summary, summary.json and a
// warning naming the stage and OpenCV's message. The board check now refuses the board, so the
// exception is raised through the bench's vision probe: the bare OpenCV matcher with a range as wide as
// its image, on every third pair.
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/calib3d.hpp>

#include "board/replay/bench_replay.h"
#include "board/replay/realtime_replay.h"
#include "tests/support/test_dive.h"
#include "tests/support/test_replay.h"

namespace deepnav {
namespace {

int g_marker_calls = 0;
int g_thrown = 0;

void sgbmThrowsOnEveryThirdPair(VisionStage stage) {
  if (stage != VisionStage::kMarkers || ++g_marker_calls % 3 != 0) return;
  ++g_thrown;
  const cv::Mat left(48, 64, CV_8UC1, cv::Scalar(100)), right(48, 64, CV_8UC1, cv::Scalar(90));
  cv::Mat disparity;
  cv::StereoSGBM::create(0, 64, 5, 0, 0, 0, 0, 0, 0, 0, cv::StereoSGBM::MODE_SGBM_3WAY)
      ->compute(left, right, disparity);
}

ReplaySummary replay(const std::string& dive, const std::string& out, void (*probe)(VisionStage)) {
  ReplayOptions o;
  o.input_path = dive;
  o.out_dir = out;
  o.vision_stage_probe = probe;
  return testing::replayOrFail(o);
}

TEST(ReplayVisionFailure, AThrowingStageCostsItsPairsNotTheReplay) {
  // GIVEN a rendered 6 s dive, replayed once untouched
  const std::string dive = testing::makeTestDive("vision_failure_dive", 6.0);
  const ReplaySummary clean = replay(dive, ::testing::TempDir() + "vision_failure_clean", nullptr);
  ASSERT_GT(clean.frames, 30u);
  EXPECT_EQ(clean.vision_failures, 0u);
  // WHEN the marker stage throws inside OpenCV on every third pair
  const std::string out = ::testing::TempDir() + "vision_failure_probe";
  const ReplaySummary s = replay(dive, out, &sgbmThrowsOnEveryThirdPair);
  // THEN the replay runs to the end: every tick and every pair
  EXPECT_EQ(s.ticks, clean.ticks);
  EXPECT_EQ(s.frames, clean.frames);
  ASSERT_FALSE(s.estimate.empty());
  EXPECT_TRUE(s.estimate.back().p_robot_in_odom_m.allFinite());
  // AND the failed pairs are counted and named
  EXPECT_GT(g_thrown, 10);
  EXPECT_EQ(s.vision_failures, static_cast<std::uint64_t>(g_thrown));
  bool warned = false;
  for (const std::string& w : s.warnings) {
    warned |= w.find(std::to_string(g_thrown) + " stereo pairs skipped: a vision stage threw") != std::string::npos &&
              w.find("markers: OpenCV") != std::string::npos;
  }
  EXPECT_TRUE(warned);
  std::ifstream json(out + "/summary.json");
  std::stringstream text;
  text << json.rdbuf();
  EXPECT_NE(text.str().find("\"vision_failures\": " + std::to_string(g_thrown)), std::string::npos);
  EXPECT_NE(formatReplaySummary(s).find(std::to_string(g_thrown) + " stereo pairs failed"), std::string::npos);
  RecordingReader recorded;
  std::string error;
  ASSERT_TRUE(recorded.open(out + "/replay.mcap", &error)) << error;
  const auto* failures = recorded.metadata("deepnav.vision_failures");
  ASSERT_NE(failures, nullptr);
  EXPECT_EQ(failures->at("pairs"), std::to_string(g_thrown));
  EXPECT_EQ(failures->at("last_stage"), "markers");
  std::printf("%d of %llu pairs threw in the marker stage; replay ran to the end, %llu ticks\n", g_thrown,
              static_cast<unsigned long long>(s.frames), static_cast<unsigned long long>(s.ticks));
}

// The same through the threaded runtime (the vision worker thread of `deepnav run`): an exception that
// escaped there reached std::terminate.
TEST(ReplayVisionFailure, AThrowingStageOnTheVisionWorkerThreadCostsItsPairsNotTheRun) {
  const std::string dive = testing::makeTestDive("vision_failure_live_dive", 4.0);
  g_marker_calls = 0;
  g_thrown = 0;
  ReplayOptions o;
  o.input_path = dive;
  o.out_dir = ::testing::TempDir() + "vision_failure_live";
  o.progress = false;
  o.vision_stage_probe = &sgbmThrowsOnEveryThirdPair;
  ReplaySummary s;
  std::string error;
  ASSERT_TRUE(runRealtimeReplay(o, &s, &error)) << error;
  EXPECT_GT(s.solutions_compared, 380u);  // the loop ran on at 100 Hz
  EXPECT_EQ(s.mismatches, 0u);
  EXPECT_GT(g_thrown, 5);
  EXPECT_EQ(s.vision_failures, static_cast<std::uint64_t>(g_thrown));
  bool warned = false;
  for (const std::string& w : s.warnings) warned |= w.find("stereo pairs skipped: a vision stage threw") != std::string::npos;
  EXPECT_TRUE(warned);
  std::printf("vision worker thread: %d pairs threw, %llu ticks reproduced\n", g_thrown,
              static_cast<unsigned long long>(s.solutions_compared));
}

}  // namespace
}  // namespace deepnav
