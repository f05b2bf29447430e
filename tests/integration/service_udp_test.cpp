// The UDP output: a listener on loopback receives one 336-byte datagram per nav tick from `deepnav run`
// and decodes it with the documented format (drivers/outputs/nav_datagram.h); sequences and times advance
// tick by tick, the CRC holds.
#include <netinet/in.h>
#include <sys/socket.h>

#include <cmath>

#include <gtest/gtest.h>

#include "drivers/outputs/nav_datagram.h"
#include "tests/support/service_fixture.h"
#include "tests/support/test_dive.h"

namespace deepnav {
namespace {

TEST(ServiceUdp, OneDatagramPerTickDecodes) {
  // GIVEN a UDP listener on a loopback port, named (twice) in outputs.udp_destinations
  const int fd = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  const std::string dest = "127.0.0.1:" + std::to_string(ntohs(a.sin_port));
  const std::string dive = testing::makeTestDive("udp_dive", 6.0, 7, false);
  const std::string board =
      testing::makeServiceBoard("udp_board", dive, {{"outputs.udp_destinations", "'" + dest + ", " + dest + "'"}});
  // WHEN deepnav runs for 3 s
  testing::DeepnavProcess run({"run", "--board", board, "--no-record", "--duration", "3"});
  std::vector<NavOutput> got;
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t bad = 0;
  while (testing::secondsSince(t0) < 8.0 && got.size() < 400) {
    pollfd p{fd, POLLIN, 0};
    if (::poll(&p, 1, 200) != 1) {
      if (!got.empty()) break;  // the run ended
      continue;
    }
    std::uint8_t buf[2048];
    const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
    NavOutput o;
    std::string error;
    if (n > 0 && decodeNavDatagram(buf, static_cast<std::size_t>(n), &o, &error)) {
      got.push_back(o);
    } else {
      ++bad;
    }
  }
  ::close(fd);
  EXPECT_EQ(run.wait(8.0), 0) << run.stderrText();
  // THEN every datagram decodes; each tick comes twice (two destinations), in order; ticks are 10 ms
  // apart (a loaded machine may make the loop skip ticks, or the outputs thread miss some)
  EXPECT_EQ(bad, 0u);
  ASSERT_GE(got.size(), 300u);  // 2 x 100 Hz over 3 s, less start-up
  std::size_t pairs = 0, steps = 0, exact = 0;
  for (std::size_t i = 1; i < got.size(); ++i) {
    const NavOutput& p = got[i - 1];
    const NavOutput& q = got[i];
    if (q.sequence == p.sequence) {
      ++pairs;
      EXPECT_EQ(q.solution.t_us, p.solution.t_us);
      continue;
    }
    ++steps;
    EXPECT_GT(q.sequence, p.sequence);
    EXPECT_GE(q.solution.t_us - p.solution.t_us, 10'000 * static_cast<std::int64_t>(q.sequence - p.sequence));
    EXPECT_EQ((q.solution.t_us - p.solution.t_us) % 10'000, 0);
    if (q.sequence == p.sequence + 1 && q.solution.t_us - p.solution.t_us == 10'000) ++exact;
  }
  EXPECT_GE(pairs, got.size() / 2 - 5);
  EXPECT_GE(exact, steps * 9 / 10);
  const NavOutput& last = got.back();
  EXPECT_NEAR(last.solution.q_odom_robot.norm(), 1.0, 1e-9);
  EXPECT_GT(last.counters.imu, 100u);
  EXPECT_GT(last.counters.ticks, 100u);
  EXPECT_EQ(last.solution.stage, NavStage::kWorkspace);
  EXPECT_GT(-last.solution.p_robot_in_odom_m.z(), 1.0);
}

}  // namespace
}  // namespace deepnav
