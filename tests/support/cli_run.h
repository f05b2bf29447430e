#pragma once
#include <string>

namespace deepnav::testing {

// What a command run through the shell left: its exit code (-1 when a signal ended it) and what it printed,
// stdout and stderr together in the order written.
struct CliRun {
  int exit_code = -1;
  std::string out;
};

// `build/bin/deepnav ARGS` as a user types it (ARGS is shell text), its output captured through a file in the
// test process's scratch directory (tempPath).
CliRun runDeepnav(const std::string& args);

}  // namespace deepnav::testing
