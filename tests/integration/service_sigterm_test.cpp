// SIGTERM (systemd's stop) ends `deepnav run` within 2 s with exit code 0 and the recording closed: the
// recording opens without truncation and the bench replay reproduces the run's solutions bit for bit.
#include <gtest/gtest.h>

#include "board/replay/bench_replay.h"
#include "drivers/replay/recording_reader.h"
#include "tests/support/service_fixture.h"
#include "tests/support/test_dive.h"

namespace deepnav {
namespace {

TEST(ServiceSigterm, StopsWithin2sAndTheRecordingReplaysBitForBit) {
  // GIVEN a rendered 5 s dive (stereo pairs keep the vision worker and the recorder busy)
  const std::string dive = testing::makeTestDive("sigterm_dive", 5.0, 7, true);
  const std::string board = testing::makeServiceBoard("sigterm_board", dive);
  const std::string recording = testing::tempPath("sigterm_run.mcap");
  testing::NotifyReceiver systemd;
  testing::DeepnavProcess run({"run", "--board", board, "--record", recording}, {{"NOTIFY_SOCKET", systemd.path()}});
  ASSERT_FALSE(systemd.receive(15.0, "READY=1").empty()) << run.stderrText();
  systemd.receive(2.0);
  // WHEN it gets SIGTERM mid-run
  const auto t0 = std::chrono::steady_clock::now();
  run.signal(SIGTERM);
  const int code = run.wait(5.0);
  const double stop_s = testing::secondsSince(t0);
  // THEN it exits cleanly within 2 s
  EXPECT_EQ(code, 0) << run.stderrText();
  EXPECT_LT(stop_s, 2.0);
  EXPECT_NE(run.stderrText().find("stopped (signal SIGTERM)"), std::string::npos) << run.stderrText();
  // AND the recording is complete (summary and footer written) and replays to the same solutions
  RecordingReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(recording, &error)) << error;
  EXPECT_FALSE(reader.truncated());
  EXPECT_GT(reader.count(Topic::kNavSolution), 100u);
  EXPECT_GT(reader.count(Topic::kLeftImage), 3u);
  ReplayOptions o;
  o.input_path = recording;
  o.out_dir = testing::tempPath("sigterm_replay");
  o.progress = false;
  ReplaySummary s;
  ASSERT_TRUE(runBenchReplay(o, &s, &error)) << error;
  EXPECT_TRUE(s.reproduce);
  EXPECT_GT(s.solutions_compared, 100u);
  EXPECT_EQ(s.mismatches, 0u);
  std::printf("stop after SIGTERM: %.3f s, %llu solutions replayed bit for bit\n", stop_s,
              static_cast<unsigned long long>(s.solutions_compared));
}

}  // namespace
}  // namespace deepnav
