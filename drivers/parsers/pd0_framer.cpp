#include "drivers/parsers/pd0_framer.h"

#include <algorithm>
#include <cstring>

#include "drivers/parsers/byte_order.h"

namespace deepnav {

bool Pd0Framer::init(size_t max_ensemble_bytes) {
  if (max_ensemble_bytes < kMinEnsembleBytes || max_ensemble_bytes > 65535) return false;
  max_bytes_ = max_ensemble_bytes;
  pending_ = 0;
  probe_ = 0;
  end_of_input_ = false;
  wait_for_certainty_ = false;
  in_lock_ = false;
  last_frame_bytes_ = 0;
  return buffer_.init(max_ensemble_bytes + 2 + 4096);
}

void Pd0Framer::flushPending() {
  if (pending_ > 0) probe_ = 0;
  buffer_.consume(pending_);
  pending_ = 0;
}

FrameStatus Pd0Framer::skip(size_t n, const char* reason, FrameError* error) {
  *error = {buffer_.offset(), n, reason};
  buffer_.consume(n);
  probe_ = 0;
  in_lock_ = false;
  return FrameStatus::kBad;
}

bool Pd0Framer::headerAt(size_t at) const {
  const uint8_t* d = buffer_.data();
  return at + 1 < buffer_.size() && d[at] == 0x7F && d[at + 1] == 0x7F;
}

Pd0Framer::Check Pd0Framer::checkAt(size_t at, size_t* frame_bytes, const char** reason, bool check_offsets) const {
  const uint8_t* d = buffer_.data() + at;
  const size_t avail = buffer_.size() - at;
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

size_t Pd0Framer::laterValidFrame() {
  return deepnav::laterValidFrame(
      buffer_.data(), buffer_.size(), 0x7F, &probe_, [this](size_t at) { return headerAt(at); },
      [this](size_t at, size_t* bytes) {
        const char* why = "";
        return checkAt(at, bytes, &why);
      });
}

// A checksum-valid frame may still be a false header whose checksum happened to hold (1 in 256 for an
// 8-bit sum, e.g. a frame cut short whose length then runs into the next one): it is refused when an
// ensemble starting inside it is valid, runs past its end and is followed by a header (or by the end
// of the input). Out of lock (after skipped bytes) the answer waits while such a later ensemble is
// incomplete (at most one maximal frame); in lock the frame is taken unless the refusal is certain,
// so the steady state of a live line never waits (a file, waitForCertainty(), always waits). The scan is a memchr over the frame: a few percent of its cost.
Pd0Framer::Overrun Pd0Framer::overrunByLaterFrame(size_t frame_bytes) const {
  return deepnav::overrunByLaterFrame(
      buffer_.data(), buffer_.size(), frame_bytes, 0x7F, end_of_input_, [this](size_t at) { return headerAt(at); },
      [this](size_t at, size_t* bytes) {
        const char* why = "";
        return checkAt(at, bytes, &why);
      });
}

FrameStatus Pd0Framer::next(RawFrame* frame, FrameError* error) {
  flushPending();
  const uint8_t* d = buffer_.data();
  const size_t size = buffer_.size();
  size_t start = 0;
  while (start + 1 < size && !(d[start] == 0x7F && d[start + 1] == 0x7F)) ++start;
  if (start > 0) {
    // Keep a trailing 0x7F: it may be the first half of the next header.
    const bool half_header = start + 1 == size && d[start] == 0x7F && !end_of_input_;
    const size_t drop = half_header ? start : (start + 1 < size ? start : size);
    if (drop > 0) return skip(drop, "no PD0 header (0x7F7F)", error);
  }
  size_t bytes = 0;
  const char* why = "";
  switch (checkAt(0, &bytes, &why, !in_lock_ || wait_for_certainty_)) {
    case Check::kBad: return skip(1, why, error);
    case Check::kValid:
      {
        // In lock on a live line the 16-bit sum is trusted (1 in 65536 cut frames pass): no scan.
        const bool scan = !in_lock_ || wait_for_certainty_;
        const Overrun o = scan ? overrunByLaterFrame(bytes) : Overrun::kNo;
        if (o == Overrun::kYes) return skip(1, "PD0 ensemble overrun by a later valid ensemble", error);
        if (o == Overrun::kNotYetKnown && (!in_lock_ || wait_for_certainty_) && !buffer_.full()) {
          return FrameStatus::kNeedMore;
        }
      }
      in_lock_ = true;
      last_frame_bytes_ = bytes;
      *frame = {buffer_.offset(), d, bytes};
      pending_ = bytes;
      return FrameStatus::kFrame;
    case Check::kIncomplete: break;
  }
  if (size == 0) return FrameStatus::kNeedMore;
  if (end_of_input_) return skip(size < 2 ? size : 1, "PD0 ensemble cut short by the end of the input", error);
  if (buffer_.full()) return skip(1, "PD0 ensemble larger than the buffer", error);
  // In lock, a frame no longer than the last one cannot hold a later one yet: no probe (steady state).
  if (in_lock_ && size <= last_frame_bytes_) return FrameStatus::kNeedMore;
  if (const size_t at = laterValidFrame(); at > 0) return skip(at, "PD0 header whose length runs over a later valid ensemble", error);
  return FrameStatus::kNeedMore;
}

}  // namespace deepnav
