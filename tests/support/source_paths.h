#pragma once
#include <string>

namespace deepnav::testing {

// The source tree and the directory of this build's binaries (absolute paths). They are compiled into one
// file, source_paths.cpp: carried by -D on every test file's command line, the clone's path made each test
// object a ccache miss in every new clone (CI builds a fresh clone each run).
const std::string& sourceDir();
const std::string& binDir();

}  // namespace deepnav::testing
