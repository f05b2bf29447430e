#include "drivers/parsers/pd0_framer.h"

#include <algorithm>
#include <cstring>

#include "drivers/parsers/byte_order.h"

namespace deepnav {

bool Pd0Framer::init(size_t max_ensemble_bytes) {
  if (max_ensemble_bytes < kMinEnsembleBytes || max_ensemble_bytes > 65535) return false;
  max_bytes_ = max_ensemble_bytes;
  return core_.init(max_ensemble_bytes + 2 + 4096);
}

bool Pd0Framer::headerAt(size_t at) const {
  const uint8_t* d = core_.buffer.data();
  return at + 1 < core_.buffer.size() && d[at] == 0x7F && d[at + 1] == 0x7F;
}

Pd0Framer::Check Pd0Framer::checkAt(size_t at, size_t* frame_bytes, const char** reason, bool check_offsets) const {
  const uint8_t* d = core_.buffer.data() + at;
  const size_t avail = core_.buffer.size() - at;
  if (avail < 6) return Check::kIncomplete;
  const size_t length = readLe16(d + 2);
  const size_t num_types = d[5];
  if (length < kMinEnsembleBytes + 2 * num_types || length > max_bytes_) {
    *reason = "PD0 ensemble length out of range";
    return Check::kBad;
  }
  *frame_bytes = length + 2;
  if (avail < length + 2) return Check::kIncomplete;
  // The data type offsets, checked as the decoder checks them, before the checksum: a run of noise
  // (0x7F 0x7F 0x7F...) then costs no checksum over a claimed length at every byte. In lock on a
  // live line the decoder's own check is enough.
  const size_t table_end = kMinEnsembleBytes + 2 * num_types;
  for (size_t i = 0; check_offsets && i < num_types; ++i) {
    const size_t begin = readLe16(d + 6 + 2 * i);
    const size_t end = i + 1 < num_types ? readLe16(d + 8 + 2 * i) : length;
    if (begin < table_end || begin + 2 > end || end > length) {
      *reason = "PD0 data type offsets out of range";
      return Check::kBad;
    }
  }
  uint32_t sum = 0;
  for (size_t i = 0; i < length; ++i) sum += d[i];
  if ((sum & 0xFFFF) != readLe16(d + length)) {
    *reason = "PD0 checksum mismatch";
    return Check::kBad;
  }
  return Check::kValid;
}

FrameStatus Pd0Framer::next(RawFrame* frame, FrameError* error) {
  core_.flushPending();
  const uint8_t* d = core_.buffer.data();
  const size_t size = core_.buffer.size();
  size_t start = 0;
  while (start + 1 < size && !(d[start] == 0x7F && d[start + 1] == 0x7F)) ++start;
  if (start > 0) {
    // Keep a trailing 0x7F: it may be the first half of the next header.
    const bool half_header = start + 1 == size && d[start] == 0x7F && !core_.end_of_input;
    const size_t drop = half_header ? start : (start + 1 < size ? start : size);
    if (drop > 0) return core_.skip(drop, "no PD0 header (0x7F7F)", error);
  }
  size_t bytes = 0;
  const char* why = "";
  switch (checkAt(0, &bytes, &why, !core_.in_lock || core_.wait_for_certainty)) {
    case Check::kBad: return core_.skip(1, why, error);
    case Check::kValid:
      // In lock on a live line the 16-bit sum is trusted (1 in 65536 cut frames pass): no scan.
      return takeValid(bytes, !core_.in_lock || core_.wait_for_certainty,
                       "PD0 ensemble overrun by a later valid ensemble", frame, error);
    case Check::kIncomplete: break;
  }
  if (size == 0) return FrameStatus::kNeedMore;
  if (core_.end_of_input) return core_.skip(size < 2 ? size : 1, "PD0 ensemble cut short by the end of the input", error);
  if (core_.buffer.full()) return core_.skip(1, "PD0 ensemble larger than the buffer", error);
  return waitOrSkipFalseHeader("PD0 header whose length runs over a later valid ensemble", error);
}

}  // namespace deepnav
