#include "drivers/parsers/pd0_framer.h"

#include "drivers/parsers/byte_order.h"

namespace deepnav {

bool Pd0Framer::init(size_t max_ensemble_bytes) {
  if (max_ensemble_bytes < kMinEnsembleBytes || max_ensemble_bytes > 65535) return false;
  max_bytes_ = max_ensemble_bytes;
  pending_ = 0;
  return buffer_.init(max_ensemble_bytes + 2 + 4096);
}

void Pd0Framer::flushPending() {
  buffer_.consume(pending_);
  pending_ = 0;
}

FrameStatus Pd0Framer::skip(size_t n, const char* reason, FrameError* error) {
  *error = {buffer_.offset(), n, reason};
  buffer_.consume(n);
  return FrameStatus::kBad;
}

FrameStatus Pd0Framer::next(RawFrame* frame, FrameError* error) {
  flushPending();
  const uint8_t* d = buffer_.data();
  const size_t size = buffer_.size();
  size_t start = 0;
  while (start + 1 < size && !(d[start] == 0x7F && d[start + 1] == 0x7F)) ++start;
  if (start > 0) {
    // Keep a trailing 0x7F: it may be the first half of the next header.
    const size_t drop = (start + 1 == size && d[start] == 0x7F) ? start : (start + 1 < size ? start : size);
    if (drop > 0) return skip(drop, "no PD0 header (0x7F7F)", error);
  }
  if (size < 6) return FrameStatus::kNeedMore;
  const size_t length = readLe16(d + 2);
  const size_t num_types = d[5];
  if (length < kMinEnsembleBytes + 2 * num_types || length > max_bytes_) {
    return skip(1, "PD0 ensemble length out of range", error);
  }
  if (size < length + 2) {
    if (buffer_.full()) return skip(1, "PD0 ensemble larger than the buffer", error);
    return FrameStatus::kNeedMore;
  }
  uint32_t sum = 0;
  for (size_t i = 0; i < length; ++i) sum += d[i];
  if ((sum & 0xFFFF) != readLe16(d + length)) return skip(1, "PD0 checksum mismatch", error);
  *frame = {buffer_.offset(), d, length + 2};
  pending_ = length + 2;
  return FrameStatus::kFrame;
}

}  // namespace deepnav
