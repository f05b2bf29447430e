#pragma once
#include <string>

namespace deepnav {

// The exit of a function that reports its error as text: sets *error (when given) to `message` and
// returns false, so that a check reads `if (bad) return fail(error, "key: must be > 0");`.
inline bool fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace deepnav
