#include "drivers/parsers/line_framer.h"

#include <algorithm>

namespace deepnav {

bool LineFramer::init(std::string_view start_chars, size_t max_line_bytes, bool restart_on_start) {
  restart_on_start_ = restart_on_start;
  scanned_ = 0;
  if (start_chars.empty() || max_line_bytes < 4) return false;
  start_chars_ = start_chars;
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
  if (start > 0 && (start < size || buffer_.full())) return skip(start, "bytes outside a sentence", error);
  if (start > 0) {
    scanned_ = start;
    return FrameStatus::kNeedMore;
  }
  if (size == 0) return FrameStatus::kNeedMore;
  for (size_t i = std::max<size_t>(scanned_, 1); i < size; ++i) {
    const uint8_t c = d[i];
    if (c == '\n') {
      const size_t len = (i > 1 && d[i - 1] == '\r') ? i - 1 : i;
      if (len > max_line_) return skip(i + 1, "line too long", error);
      *frame = {buffer_.offset(), d, len};
      pending_ = i + 1;
      scanned_ = 0;
      return FrameStatus::kFrame;
    }
    if (i >= max_line_ + 1) return skip(i, "line too long", error);
    if (restart_on_start_ && isStart(c)) return skip(i, "sentence cut short by a new start character", error);
    if ((c < 0x20 && c != '\r' && c != '\t') || c >= 0x7F) return skip(i + 1, "non-ASCII byte in a sentence", error);
  }
  scanned_ = size;
  return FrameStatus::kNeedMore;
}

}  // namespace deepnav
