// The threaded vehicle runtime (nav loop thread, vision worker, recorder thread) fed by a replay driver
// thread at real speed: its recording must be reproduced bit for bit by the bench replay.
#include <gtest/gtest.h>

#include "board/replay/realtime_replay.h"
#include "tests/support/test_dive.h"

namespace deepnav {
namespace {

TEST(LiveLoop, RealTimeRunIsRecordedAndReproducedBitForBit) {
  // GIVEN a 4 s simulated dive WHEN it plays in real time through the threaded runtime
  const std::string dive = testing::makeTestDive("live_dive", 4.0);
  ReplayOptions o;
  o.input_path = dive;
  o.out_dir = ::testing::TempDir() + "live_out";
  o.progress = false;
  ReplaySummary s;
  std::string error;
  ASSERT_TRUE(runRealtimeReplay(o, &s, &error)) << error;
  // THEN the loop ran at 100 Hz over the dive, consumed every IMU sample, and its recording replays exactly
  EXPECT_TRUE(s.reproduce);
  EXPECT_GT(s.solutions_compared, 380u);
  EXPECT_EQ(s.mismatches, 0u);
  EXPECT_GE(s.inputs.imu, 400u);
  EXPECT_GT(s.inputs.accepted, 0u);
  EXPECT_GE(s.loop.ticks, s.solutions_compared);
  EXPECT_EQ(s.loop.task_count, 3);
  EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
}

}  // namespace
}  // namespace deepnav
