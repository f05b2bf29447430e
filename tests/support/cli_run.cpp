#include "tests/support/cli_run.h"

#include <sys/wait.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "tests/support/source_paths.h"
#include "tests/support/temp_path.h"

namespace deepnav::testing {

CliRun runDeepnav(const std::string& args) {
  static std::atomic<int> calls{0};
  const std::string log = tempPath("cli_run_" + std::to_string(calls++) + ".txt");
  const std::string cmd = binDir() + "/deepnav " + args + " > " + log + " 2>&1";
  CliRun r;
  const int status = std::system(cmd.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  r.out.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  std::filesystem::remove(log);
  return r;
}

}  // namespace deepnav::testing
