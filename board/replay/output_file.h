#pragma once
#include <fstream>
#include <string>

namespace deepnav {

// The replay's output files (trajectory.tum, summary.json, *.csv): a failure names the file and the
// system's reason, e.g. "out/summary.json: cannot write: No space left on device".

// Creates the output directory (--out) if needed. An empty name is refused: the outputs would land in
// the root directory ("" + "/summary.json").
bool prepareOutputDir(const std::string& dir, std::string* error);

// Opens path for writing; false with *error on failure.
bool openOutput(std::ofstream* out, const std::string& path, std::string* error);

// Flushes and closes out (written to path); false with *error when any write or the close failed.
bool closeOutput(std::ofstream* out, const std::string& path, std::string* error);

// "path: cannot write: <strerror(errno_value)>" ("...: write error" when errno_value is 0).
std::string writeFailure(const std::string& path, int errno_value);

}  // namespace deepnav
