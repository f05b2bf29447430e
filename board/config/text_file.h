#pragma once
#include <string>

namespace deepnav {

// Reads a whole (small) text file: board, panel or scenario files at start-up. False with
// "<path>: cannot open <what>" on error.
bool readTextFile(const std::string& path, const std::string& what, std::string* text, std::string* error);

}  // namespace deepnav
