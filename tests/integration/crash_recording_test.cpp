// kill -9 during recording: the recording stays readable up to its last complete chunk (at most about a
// second before the kill), and what it holds replays bit for bit.
#include <csignal>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "board/replay/bench_replay.h"
#include "drivers/replay/recording_reader.h"
#include "tests/support/test_dive.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

pid_t startRealtimeReplay(const std::string& dive, const std::string& out) {
  const pid_t pid = fork();
  if (pid == 0) {
    const int devnull = open("/dev/null", O_WRONLY);
    dup2(devnull, STDOUT_FILENO);
    dup2(devnull, STDERR_FILENO);
    const std::string exe = deepnav::testing::binDir() + "/deepnav";
    execl(exe.c_str(), "deepnav", "replay", dive.c_str(), "--out", out.c_str(), "--realtime", nullptr);
    _exit(127);
  }
  return pid;
}

// Waits until the recording being written holds at least `solutions` navigation solutions in complete chunks
// (it is opened as a cut-off file, as after a crash), so the kill lands with seconds of run on disk however
// slowly the process started (an instrumented build takes several seconds to its first tick). False after
// timeout_s.
bool waitForSolutionsOnDisk(const std::string& path, std::uint64_t solutions, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    RecordingReader reader;
    std::string error;
    if (reader.open(path, &error) && reader.count(Topic::kNavSolution) >= solutions) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  return false;
}

TEST(CrashSafety, KillDuringRecordingLeavesAReadableRecording) {
  // GIVEN the vehicle runtime recording a 10 s dive in real time
  const std::string dive = testing::makeTestDive("crash_dive", 10.0);
  const std::string out = ::testing::TempDir() + "crash_out";
  std::filesystem::remove_all(out);
  const pid_t pid = startRealtimeReplay(dive, out);
  ASSERT_GT(pid, 0);
  // WHEN it is killed with SIGKILL once 3 s of 100 Hz solutions are on disk, mid-way through the next chunk
  const bool on_disk = waitForSolutionsOnDisk(out + "/live.mcap", 300, 120.0);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  EXPECT_TRUE(on_disk) << "fewer than 300 solutions on disk after 120 s";
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  // THEN the recording opens, says it was cut off, and keeps all but at most the last ~1 s of the run
  RecordingReader reader;
  std::string error;
  ASSERT_TRUE(reader.open(out + "/live.mcap", &error)) << error;
  EXPECT_TRUE(reader.truncated());
  ReplayOptions o;
  o.input_path = out + "/live.mcap";
  o.out_dir = out + "/after";
  o.progress = false;
  ReplaySummary s;
  ASSERT_TRUE(runBenchReplay(o, &s, &error)) << error;
  EXPECT_TRUE(s.reproduce);
  EXPECT_GT(s.solutions_compared, 200u);  // >= 2 s of 100 Hz ticks survived (4 s - start-up - 1 chunk)
  EXPECT_EQ(s.mismatches, 0u);
  EXPECT_FALSE(s.warnings.empty());
}

}  // namespace
}  // namespace deepnav
