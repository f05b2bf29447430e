#pragma once
#include <filesystem>
#include <string>

namespace deepnav::testing {

// The source tree and the directory of this build's binaries (absolute paths). They are compiled into one
// file, source_paths.cpp: carried by -D on every test file's command line, the clone's path made each test
// object a ccache miss in every new clone (CI builds a fresh clone each run).
const std::string& sourceDir();
const std::string& binDir();

// The project's shared data (Middlebury pairs, DVL, NMEA and CAN captures, EuRoC, underwater frames):
// $DEEPNAV_SHARED_DATA, else ../shared/data beside the source tree. It may be absent: a test that needs
// it checks that its file exists and skips otherwise.
std::filesystem::path sharedDataDir();

}  // namespace deepnav::testing
