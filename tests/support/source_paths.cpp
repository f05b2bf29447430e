#include "tests/support/source_paths.h"

namespace deepnav::testing {

const std::string& sourceDir() {
  static const std::string dir = DEEPNAV_SOURCE_DIR;
  return dir;
}

const std::string& binDir() {
  static const std::string dir = DEEPNAV_BIN_DIR;
  return dir;
}

}  // namespace deepnav::testing
