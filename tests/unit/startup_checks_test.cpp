// The start-up probes `deepnav run --validate` shares with run (board/service/startup_checks.h).
#include "board/service/startup_checks.h"
#include "tests/support/temp_path.h"

#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

namespace deepnav {
namespace {

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

TEST(StartupChecks, DirectoriesRunWouldCreateOrWrite) {
  const std::string base = deepnav::testing::tempPath("startup_checks");
  std::filesystem::create_directories(base);
  const std::string file = base + "/file";
  std::ofstream(file) << "x";
  std::string why;
  EXPECT_TRUE(directoryUsable(base, &why)) << why;
  EXPECT_TRUE(directoryUsable(base + "/new/deeper", &why)) << why;  // created by run
  EXPECT_FALSE(directoryUsable(file, &why));
  EXPECT_EQ(why, file + " exists and is not a directory");
  EXPECT_FALSE(directoryUsable(file + "/run", &why));
  EXPECT_EQ(why, file + "/run cannot be created: " + file + " is not a directory");
  std::filesystem::remove_all(base);
}

TEST(StartupChecks, TcpListenAddressMustBeLocalAndThePortFree) {
  std::string why;
  bool foreign = false;
  EXPECT_TRUE(tcpListenable("127.0.0.1", 0, &why, &foreign)) << why;
  EXPECT_FALSE(tcpListenable("192.0.2.7", 0, &why, &foreign));  // TEST-NET-1: never this host's
  EXPECT_TRUE(foreign);
  EXPECT_TRUE(has(why, "not an address of this host")) << why;
  // A port somebody listens on.
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in a{};
  a.sin_family = AF_INET;
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&a), sizeof a), 0);
  ASSERT_EQ(::listen(fd, 1), 0);
  socklen_t len = sizeof a;
  ::getsockname(fd, reinterpret_cast<sockaddr*>(&a), &len);
  EXPECT_FALSE(tcpListenable("127.0.0.1", ntohs(a.sin_port), &why, &foreign));
  EXPECT_FALSE(foreign);
  EXPECT_TRUE(has(why, "Address already in use")) << why;
  ::close(fd);
}

TEST(StartupChecks, CanInterfaceMustBeASocketCanLink) {
  std::string why;
  EXPECT_FALSE(canInterfaceUsable("lo", &why));
  // The link type is checked before the kernel's CAN support: the answer is the same on any machine.
  EXPECT_TRUE(has(why, "is not a CAN interface (link type 772, loopback")) << why;
}

TEST(StartupChecks, CpuSetMustMeetTheProcessAffinity) {
  cpu_set_t allowed;
  ASSERT_EQ(::sched_getaffinity(0, sizeof allowed, &allowed), 0);
  std::string why;
  EXPECT_TRUE(cpusAvailable(allowed, &why)) << why;
  cpu_set_t none;
  CPU_ZERO(&none);
  EXPECT_FALSE(cpusAvailable(none, &why));
  EXPECT_TRUE(has(why, "none of these CPUs is available to this process (it may use ")) << why;
}

}  // namespace
}  // namespace deepnav
