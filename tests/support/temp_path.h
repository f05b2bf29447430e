#pragma once
#include <unistd.h>

#include <string>

#include <gtest/gtest.h>

namespace deepnav::testing {

// ctest runs each test case as its own process, two at a time: a file that several cases of one binary
// write (a fixture's shared input, a replay's output directory) needs a per-process name, or one case
// reads what the other is still writing.
inline std::string tempPath(const std::string& name) {
  return ::testing::TempDir() + "deepnav_" + std::to_string(::getpid()) + "_" + name;
}

}  // namespace deepnav::testing
