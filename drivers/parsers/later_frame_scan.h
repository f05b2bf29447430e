#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace deepnav {

// The resynchronisation scans shared by the binary framers (Pd0Framer, XbusFramer): each framer says
// where a header starts (header(at)) and what the candidate frame there is (check(at, &bytes)); the
// scans over the bytes it holds are the same. No allocation.
enum class FrameCheck { kBad, kIncomplete, kValid };
enum class FrameOverrun { kNo, kYes, kNotYetKnown };

// Position of the first later frame that is complete, checksum-valid and followed by a header, or 0.
// The probe stops at a later candidate still incomplete (it may be the first real frame) and resumes
// there on the next call (*probe), so each held byte is examined once per first header: linear cost.
template <class HeaderAt, class CheckAt>
size_t laterValidFrame(const uint8_t* d, size_t size, uint8_t first_byte, size_t* probe, HeaderAt header,
                       CheckAt check) {
  size_t& p = *probe;
  for (p = std::max<size_t>(p, 1); p + 1 < size; ++p) {
    const void* first = std::memchr(d + p, first_byte, size - 1 - p);
    if (first == nullptr) {
      p = size - 1;
      break;
    }
    p = size_t(static_cast<const uint8_t*>(first) - d);
    if (!header(p)) continue;
    size_t bytes = 0;
    const FrameCheck c = check(p, &bytes);
    if (c == FrameCheck::kIncomplete) return 0;
    if (c == FrameCheck::kBad) continue;
    if (p + bytes + 2 > size) return 0;  // wait for the next header's first two bytes
    if (header(p + bytes)) return p;
  }
  return 0;
}

// A checksum-valid frame may still be a false header whose checksum happened to hold (1 in 256 for an
// 8-bit sum, e.g. a frame cut short whose length then runs into the next one): kYes when a frame
// starting inside its first frame_bytes is valid, runs past its end and is followed by a header (or by
// the end of the input); kNotYetKnown while such a later frame is incomplete. The scan is a memchr over
// the frame: a few percent of its cost.
template <class HeaderAt, class CheckAt>
FrameOverrun overrunByLaterFrame(const uint8_t* d, size_t size, size_t frame_bytes, uint8_t first_byte,
                                 bool end_of_input, HeaderAt header, CheckAt check) {
  bool unknown = false;
  for (size_t at = 1; at < frame_bytes; ++at) {
    const void* first = std::memchr(d + at, first_byte, frame_bytes - at);
    if (first == nullptr) break;
    at = size_t(static_cast<const uint8_t*>(first) - d);
    if (!header(at)) continue;
    size_t bytes = 0;
    const FrameCheck c = check(at, &bytes);
    if (c == FrameCheck::kIncomplete) unknown = unknown || !end_of_input;
    if (c != FrameCheck::kValid || at + bytes <= frame_bytes) continue;
    if (header(at + bytes) || (end_of_input && at + bytes == size)) return FrameOverrun::kYes;
    unknown = unknown || (!end_of_input && at + bytes + 2 > size);
  }
  return unknown ? FrameOverrun::kNotYetKnown : FrameOverrun::kNo;
}

}  // namespace deepnav
