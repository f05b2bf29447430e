#pragma once
#include <cstddef>
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

// The same, for a line that may carry junk before the frame (a stray byte, noise without a line end):
// when the whole line does not parse, it is parsed again from after its last control or non-ASCII
// byte, from its last '(' (log format) and from the interface before its last "[n]" (default format).
// A comment line is searched the same way (a stray '#' before a frame). *junk_bytes is how many
// leading bytes were dropped that way (0 otherwise).
CandumpLine parseCandumpLineAfterJunk(std::string_view line, CanFrame* frame, double* t_s, const char** error,
                                      size_t* junk_bytes);

}  // namespace deepnav
