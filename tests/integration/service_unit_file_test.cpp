// board/systemd/deepnav.service passes `systemd-analyze verify` with nothing on stderr. verify also
// checks that ExecStart's binary exists, so the check runs on a copy whose ExecStart names the binary
// just built (the .deb test checks /usr/bin/deepnav itself). Skipped where systemd-analyze is absent.
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "tests/support/service_fixture.h"
#include "tests/support/source_paths.h"

namespace deepnav {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ServiceUnitFile, SystemdAnalyzeVerifyIsClean) {
  if (::access("/usr/bin/systemd-analyze", X_OK) != 0) GTEST_SKIP() << "systemd-analyze not installed";
  std::string unit = readFile(deepnav::testing::sourceDir() + "/board/systemd/deepnav.service");
  // The unit is the notify type with a watchdog, restarts on failure, and runs the service command.
  EXPECT_NE(unit.find("\nType=notify\n"), std::string::npos);
  EXPECT_NE(unit.find("\nWatchdogSec="), std::string::npos);
  EXPECT_NE(unit.find("\nRestart=on-failure\n"), std::string::npos);
  const std::string exec = "ExecStart=/usr/bin/deepnav run --board /etc/deepnav/board.yaml";
  const auto at = unit.find(exec);
  ASSERT_NE(at, std::string::npos);
  unit.replace(at, std::string("ExecStart=/usr/bin/deepnav").size(), "ExecStart=" + deepnav::testing::binDir() + "/deepnav");
  const std::string dir = testing::tempPath("unit");
  ASSERT_EQ(std::system(("mkdir -p " + dir).c_str()), 0);
  std::ofstream(dir + "/deepnav.service") << unit;
  const std::string err = dir + "/verify.err";
  const int rc = std::system(("systemd-analyze verify " + dir + "/deepnav.service 2>" + err + " >/dev/null").c_str());
  EXPECT_EQ(rc, 0);
  EXPECT_EQ(readFile(err), "");
}

}  // namespace
}  // namespace deepnav
