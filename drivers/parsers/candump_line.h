#pragma once
#include <string_view>

#include "drivers/parsers/can_frame.h"

namespace deepnav {

// One line of a candump capture, in either of the two formats candump writes:
//   "  can0  09F8027F   [8]  00 FC FF FF 00 00 FF FF"   (default)
//   "(1436509052.249713) can0 09F8027F#00FCFFFF0000FFFF"  (-l log format)
// An identifier of more than 3 hex digits is a 29-bit one. Comment lines ('#') and blank lines return
// kSkip; anything else that does not parse is kInvalid.
enum class CandumpLine { kFrame, kSkip, kInvalid };

CandumpLine parseCandumpLine(std::string_view line, CanFrame* frame, double* t_s, const char** error);

}  // namespace deepnav
