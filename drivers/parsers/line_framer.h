#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "drivers/parsers/frame_result.h"
#include "drivers/parsers/stream_buffer.h"

namespace deepnav {

// Splits an ASCII stream into lines for the text protocols (NMEA 0183, PD6, Water Linked). A line
// starts at one of `start_chars` (e.g. "$!" for NMEA) and ends at '\n' or '\r' (a bare CR ends a
// line too; the LF of CR LF is then skipped as a blank line). Bytes before a start character are
// skipped and reported; a line longer than max_line_bytes, or interrupted by a new start character or
// a control/non-ASCII byte, is reported and skipped, and the search resumes at the next start
// character. The frame holds the line without its terminator. After endOfInput() the last line is
// framed without its terminator.
class LineFramer {
 public:
  // start_chars and whole_line_starts must outlive the framer (string literals). restart_on_start: a
  // start character inside a line means the line was cut short (true for NMEA, PD6, Water Linked
  // serial). Lines beginning with one of `whole_line_starts` are never cut that way (JSON objects,
  // which hold '{' themselves).
  bool init(std::string_view start_chars, size_t max_line_bytes, bool restart_on_start = true,
            std::string_view whole_line_starts = {});
  size_t push(const uint8_t* data, size_t n) { return flushPending(), buffer_.append(data, n); }
  // No byte will follow (end of a file): a last line without its terminator is framed.
  void endOfInput() { end_of_input_ = true; }
  FrameStatus next(RawFrame* frame, FrameError* error);

 private:
  void flushPending();
  bool isStart(uint8_t c) const { return is_start_[c]; }
  bool restartsLine(uint8_t first) const {
    return restart_on_start_ && whole_line_starts_.find(char(first)) == std::string_view::npos;
  }
  FrameStatus skip(size_t n, const char* reason, FrameError* error);
  FrameStatus lineAt(size_t end, size_t resume, RawFrame* frame, FrameError* error);

  StreamBuffer buffer_;
  std::array<bool, 256> is_start_{};  // start_chars_ as a table: tested on every byte
  std::string_view start_chars_;
  std::string_view whole_line_starts_;
  size_t max_line_ = 0;
  bool restart_on_start_ = true;
  bool end_of_input_ = false;
  size_t pending_ = 0;
  size_t scanned_ = 0;  // bytes of the current line (or noise run) already checked
};

}  // namespace deepnav
