#pragma once
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

#include <gtest/gtest.h>

namespace deepnav::testing {

// One scratch directory per test process, removed when the process exits. ctest runs each test case as its
// own process, two at a time: a file that several cases of one binary write (a fixture's shared input, a
// replay's output directory) needs a per-process name, or one case reads what the other is still writing;
// and per-process names left behind fill the disk (a few hundred MB per fixture, every run). Set
// DEEPNAV_KEEP_TEST_FILES=1 to keep the directory for a post-mortem.
class ProcessTempDir {
 public:
  ProcessTempDir() : path_(::testing::TempDir() + "deepnav_" + std::to_string(::getpid())) {
    std::error_code ignored;
    std::filesystem::create_directories(path_, ignored);
  }
  ~ProcessTempDir() {
    if (std::getenv("DEEPNAV_KEEP_TEST_FILES") != nullptr) return;
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ProcessTempDir(const ProcessTempDir&) = delete;
  ProcessTempDir& operator=(const ProcessTempDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

inline std::string tempPath(const std::string& name) {
  static const ProcessTempDir dir;
  return dir.path() + "/" + name;
}

}  // namespace deepnav::testing
