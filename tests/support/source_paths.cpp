#include "tests/support/source_paths.h"

#include <cstdlib>

namespace deepnav::testing {

const std::string& sourceDir() {
  static const std::string dir = DEEPNAV_SOURCE_DIR;
  return dir;
}

const std::string& binDir() {
  static const std::string dir = DEEPNAV_BIN_DIR;
  return dir;
}

std::filesystem::path sharedDataDir() {
  if (const char* env = std::getenv("DEEPNAV_SHARED_DATA")) return env;
  return std::filesystem::path(sourceDir()) / ".." / "shared" / "data";
}

}  // namespace deepnav::testing
