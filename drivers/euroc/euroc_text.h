#pragma once
#include <string>

namespace deepnav {

// The text without its leading and trailing blanks (space, tab, and the CR of CRLF files), as the
// EuRoC CSV and sensor.yaml readers compare fields and keys.
inline std::string trimEurocBlanks(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

// "path:line: what" into *error (when given); returns false. The readers' error for a bad line.
inline bool failAtLine(const std::string& path, int line, const std::string& what, std::string* error) {
  if (error) *error = path + ":" + std::to_string(line) + ": " + what;
  return false;
}

}  // namespace deepnav
