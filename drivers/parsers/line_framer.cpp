#include "drivers/parsers/line_framer.h"

#include <algorithm>

namespace deepnav {

bool LineFramer::init(std::string_view start_chars, size_t max_line_bytes, bool restart_on_start,
                      std::string_view whole_line_starts) {
  restart_on_start_ = restart_on_start;
  whole_line_starts_ = whole_line_starts;
  scanned_ = 0;
  end_of_input_ = false;
  if (start_chars.empty() || max_line_bytes < 4) return false;
  start_chars_ = start_chars;
  is_start_.fill(false);
  for (const char c : start_chars) is_start_[uint8_t(c)] = true;
  max_line_ = max_line_bytes;
  pending_ = 0;
  return buffer_.init(max_line_bytes + 2 + 4096);
}

void LineFramer::flushPending() {
  if (pending_ > 0) scanned_ = 0;
  buffer_.consume(pending_);
  pending_ = 0;
}

FrameStatus LineFramer::skip(size_t n, const char* reason, FrameError* error) {
  *error = {buffer_.offset(), n, reason};
  buffer_.consume(n);
  scanned_ = 0;
  return FrameStatus::kBad;
}

// The line [0, end) is complete; the next line is searched from `resume`.
FrameStatus LineFramer::lineAt(size_t end, size_t resume, RawFrame* frame, FrameError* error) {
  if (end > max_line_) return skip(resume, "line too long", error);
  *frame = {buffer_.offset(), buffer_.data(), end};
  pending_ = resume;
  scanned_ = 0;
  return FrameStatus::kFrame;
}

FrameStatus LineFramer::next(RawFrame* frame, FrameError* error) {
  flushPending();
  const uint8_t* d = buffer_.data();
  const size_t size = buffer_.size();
  size_t start = 0;
  // Blank line ends and whitespace between lines are not errors.
  while (start < size && (d[start] == '\r' || d[start] == '\n' || d[start] == ' ')) ++start;
  if (start > 0) {
    buffer_.consume(start);
    scanned_ = 0;
    return next(frame, error);
  }
  // Resume where the previous call stopped: bytes arrive in small reads, a rescan would be quadratic.
  start = (size > 0 && !isStart(d[0])) ? scanned_ : 0;
  while (start < size && !isStart(d[start])) ++start;
  // Noise is reported in one piece, once the next sentence starts (or the window is full).
  if (start > 0 && (start < size || buffer_.full() || end_of_input_)) return skip(start, "bytes outside a sentence", error);
  if (start > 0) {
    scanned_ = start;
    return FrameStatus::kNeedMore;
  }
  if (size == 0) return FrameStatus::kNeedMore;
  const bool restart = restartsLine(d[0]);
  for (size_t i = std::max<size_t>(scanned_, 1); i < size; ++i) {
    const uint8_t c = d[i];
    if (c == '\n' || c == '\r') return lineAt(i, i + 1, frame, error);
    if (i >= max_line_ + 1) return skip(i, "line too long", error);
    if (restart && isStart(c)) return skip(i, "sentence cut short by a new start character", error);
    if ((c < 0x20 && c != '\t') || c >= 0x7F) return skip(i + 1, "non-ASCII byte in a sentence", error);
  }
  scanned_ = size;
  if (end_of_input_) return lineAt(size, size, frame, error);
  if (buffer_.full()) return skip(size, "line too long", error);
  return FrameStatus::kNeedMore;
}

}  // namespace deepnav
