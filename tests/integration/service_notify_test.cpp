// `deepnav run` speaks systemd's notify protocol: READY=1 once running, WATCHDOG=1 at half the watchdog
// interval only while the nav loop ticks, STATUS= with stage, health and sensors, STOPPING=1 at the end.
// A receiver bound on NOTIFY_SOCKET plays systemd (PID 1 here is not systemd).
#include <atomic>
#include <cstdlib>
#include <thread>

#include <gtest/gtest.h>

#include "board/service/deepnav_service.h"
#include "tests/support/service_fixture.h"
#include "tests/support/test_dive.h"

namespace deepnav {
namespace {

using testing::NotifyReceiver;

std::vector<double> watchdogTimes(const std::vector<NotifyReceiver::Message>& messages) {
  std::vector<double> t;
  for (const auto& m : messages) {
    if (testing::hasLine(m.text, "WATCHDOG=1")) t.push_back(m.t_s);
  }
  return t;
}

TEST(ServiceNotify, ReadyThenWatchdogAtHalfTheIntervalAndStatusWithStageAndHealth) {
  // GIVEN a 6 s dive and a receiver on NOTIFY_SOCKET, WATCHDOG_USEC = 0.6 s
  const std::string dive = testing::makeTestDive("notify_dive", 6.0, 7, false);
  const std::string board = testing::makeServiceBoard("notify_board", dive);
  NotifyReceiver systemd;
  // WHEN deepnav runs for 3 s
  testing::DeepnavProcess run({"run", "--board", board, "--no-record", "--duration", "3"},
                              {{"NOTIFY_SOCKET", systemd.path()}, {"WATCHDOG_USEC", "600000"}});
  const auto ready = systemd.receive(10.0, "READY=1");
  ASSERT_FALSE(ready.empty()) << run.stderrText();
  ASSERT_TRUE(testing::hasLine(ready.back().text, "READY=1")) << run.stderrText();
  for (const auto& m : ready) EXPECT_FALSE(testing::hasLine(m.text, "WATCHDOG=1")) << "watchdog before READY";
  const auto messages = systemd.receive(6.0, "STOPPING=1");
  EXPECT_EQ(run.wait(5.0), 0) << run.stderrText();
  // THEN WATCHDOG=1 comes every 0.3 s (half the interval), never later than the interval
  const std::vector<double> t = watchdogTimes(messages);
  ASSERT_GE(t.size(), 7u);
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_LT(t[i] - t[i - 1], 0.6) << "gap before ping " << i;
  EXPECT_GT((t.back() - t.front()) / static_cast<double>(t.size() - 1), 0.2);
  // AND STATUS= names the stage, the health and each sensor's state and count
  std::string status;
  for (const auto& m : messages) {
    if (m.text.rfind("STATUS=stage", 0) == 0) status = m.text;
  }
  ASSERT_FALSE(status.empty());
  EXPECT_NE(status.find("stage 1 workspace"), std::string::npos) << status;
  EXPECT_NE(status.find("| health "), std::string::npos) << status;
  EXPECT_NE(status.find("imu ok ("), std::string::npos) << status;
  EXPECT_NE(status.find("dvl ok ("), std::string::npos) << status;
  EXPECT_NE(status.find("ticks "), std::string::npos) << status;
  // AND the run ends with STOPPING=1
  ASSERT_FALSE(messages.empty());
  EXPECT_TRUE(testing::hasLine(messages.back().text, "STOPPING=1")) << messages.back().text;
}

// Blocks the loop thread (the observer runs on it) while `stall` is set: a real stalled loop.
class StallingObserver : public TickObserver {
 public:
  std::atomic<bool> stall{false};
  std::atomic<bool> stalled{false};
  void onTick(const NavSolution&, const InputCounters&) override {
    while (stall.load()) {
      stalled.store(true);
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  }
};

TEST(ServiceNotify, StalledLoopStopsTheWatchdogAndStatusSaysStalled) {
  // GIVEN the service in this process, with a watchdog of 0.4 s
  const std::string dive = testing::makeTestDive("stall_dive", 8.0, 7, false);
  const std::string board = testing::makeServiceBoard("stall_board", dive);
  NotifyReceiver systemd;
  ::setenv("NOTIFY_SOCKET", systemd.path().c_str(), 1);
  ::setenv("WATCHDOG_USEC", "400000", 1);
  StallingObserver observer;
  ServiceOptions o;
  o.board_path = board;
  o.no_recording = true;
  o.tick_observer = &observer;
  DeepnavService service;
  std::string error;
  ASSERT_TRUE(service.init(o, &error)) << error;
  bool run_ok = false;
  std::thread runner([&] { run_ok = service.run(nullptr, &error); });
  ASSERT_FALSE(systemd.receive(5.0, "READY=1").empty());
  const auto healthy = watchdogTimes(systemd.receive(1.0));
  // WHEN the loop thread stalls for 1.5 s
  observer.stall.store(true);
  const double stall_start_s = systemd.now();
  while (!observer.stalled.load()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const auto during = systemd.receive(1.5);
  observer.stall.store(false);
  const auto after = systemd.receive(1.0);
  service.requestStop();
  runner.join();
  EXPECT_TRUE(run_ok) << error;
  // THEN pings came before; during the stall only the ping of the window the stall began in (and one
  // queued just before it) arrive, none after the stall's first 0.2 s window; they resume after it
  EXPECT_GE(healthy.size(), 4u);
  const auto stalled_pings = watchdogTimes(during);
  EXPECT_LE(stalled_pings.size(), 2u);
  for (double t : stalled_pings) EXPECT_LT(t - stall_start_s, 0.3) << "a ping while the loop was stalled";
  EXPECT_GE(watchdogTimes(after).size(), 3u);
  bool status_stalled = false;
  for (const auto& m : during) status_stalled |= m.text.find("health stalled") != std::string::npos;
  EXPECT_TRUE(status_stalled) << "no STATUS= with 'health stalled' during the stall";
  ::unsetenv("NOTIFY_SOCKET");
  ::unsetenv("WATCHDOG_USEC");
}

}  // namespace
}  // namespace deepnav
