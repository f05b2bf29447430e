// The service's tick observer runs on the nav loop thread at every tick: it must not allocate. Every
// allocation made on the test thread while it plays the loop thread is counted (operator new and, outside
// sanitizer builds, malloc), with the Modbus server and the UDP sender live behind it.
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include <gtest/gtest.h>

#include "board/config/vehicle_setup.h"
#include "board/loop/live_loop.h"
#include "board/service/output_publisher.h"

#include "tests/support/alloc_counter.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

TEST(ServiceAlloc, TickObserverAllocatesNothing) {
  // GIVEN the sim board's loop (not started: this thread plays the loop thread) and live outputs
  VehicleSetup setup;
  std::string error;
  ASSERT_TRUE(loadVehicleSetup(deepnav::testing::sourceDir() + "/board/sim/board.yaml", &setup, &error)) << error;
  LiveLoop loop;
  ASSERT_TRUE(loop.init(setup, "", &error)) << error;
  const int udp = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(udp, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  socklen_t len = sizeof a;
  ::getsockname(udp, reinterpret_cast<sockaddr*>(&a), &len);
  BoardConfig::Outputs outputs = setup.config.outputs;
  outputs.modbus_enabled = true;
  outputs.modbus_address = "127.0.0.1";
  outputs.modbus_port = 0;  // any free port
  outputs.udp_destinations = "127.0.0.1:" + std::to_string(ntohs(a.sin_port));
  OutputPublisher publisher;
  ASSERT_TRUE(publisher.start(outputs, &loop, &error)) << error;
  NavSolution s;
  InputCounters c;
  publisher.onTick(s, c);  // warm-up
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  // WHEN 500 ticks are published at 1 kHz
  t_counting = true;
  for (int i = 0; i < 500; ++i) {
    s.t_us += 10'000;
    ++c.imu;
    publisher.onTick(s, c);
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  t_counting = false;
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  publisher.stop();
  ::close(udp);
  // THEN nothing was allocated on the loop thread, and the outputs thread did its work
  EXPECT_EQ(g_allocations.load(), 0);
  EXPECT_EQ(publisher.latest().solution.t_us, s.t_us);
  EXPECT_GT(publisher.datagramsSent(), 400u);
}

}  // namespace
}  // namespace deepnav
