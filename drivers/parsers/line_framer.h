#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/frame_result.h"
#include "drivers/parsers/stream_buffer.h"

namespace deepnav {

// Splits an ASCII stream into lines for the text protocols (NMEA 0183, PD6, Water Linked). A line
// starts at one of `start_chars` (e.g. "$!" for NMEA) and ends at '\n' (a '\r' before it is dropped).
// Bytes before a start character are skipped and reported; a line longer than max_line_bytes, or
// interrupted by a new start character or a control/non-ASCII byte, is reported and skipped, and the
// search resumes at the next start character. The frame holds the line without its terminator.
class LineFramer {
 public:
  // start_chars must outlive the framer (a string literal). restart_on_start: a start character
  // inside a line means the line was cut short (true for NMEA and PD6, false for JSON).
  bool init(std::string_view start_chars, size_t max_line_bytes, bool restart_on_start = true);
  size_t push(const uint8_t* data, size_t n) { return flushPending(), buffer_.append(data, n); }
  FrameStatus next(RawFrame* frame, FrameError* error);

 private:
  void flushPending();
  bool isStart(uint8_t c) const { return start_chars_.find(char(c)) != std::string_view::npos; }
  FrameStatus skip(size_t n, const char* reason, FrameError* error);

  StreamBuffer buffer_;
  std::string_view start_chars_;
  size_t max_line_ = 0;
  bool restart_on_start_ = true;
  size_t pending_ = 0;
  size_t scanned_ = 0;  // bytes of the current line (or noise run) already checked
};

}  // namespace deepnav
