#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/frame_result.h"
#include "drivers/parsers/stream_buffer.h"

namespace deepnav {

// The state every binary framer (Pd0Framer, XbusFramer) keeps around its own header and frame checks:
// the held bytes, the frame returned last (consumed on the next call), where the scan for a later
// frame resumes, the lock, and how the input ends. No allocation after init().
struct BinaryFramerCore {
  StreamBuffer buffer;
  size_t pending = 0;  // bytes of the last returned frame, consumed on the next call
  size_t probe = 0;    // next buffer position the probe for a later frame examines (0: not started)
  bool end_of_input = false;        // no byte will follow (endOfInput())
  bool wait_for_certainty = false;  // the bytes come from a file (waitForCertainty())
  size_t last_frame_bytes = 0;      // size of the last frame returned
  bool in_lock = false;  // the frame at the front follows a returned frame, nothing skipped between

  bool init(size_t capacity) {
    pending = 0;
    probe = 0;
    end_of_input = false;
    wait_for_certainty = false;
    in_lock = false;
    last_frame_bytes = 0;
    return buffer.init(capacity);
  }

  size_t push(const uint8_t* data, size_t n) { return flushPending(), buffer.append(data, n); }

  // Consumes the frame returned last.
  void flushPending() {
    if (pending > 0) probe = 0;
    buffer.consume(pending);
    pending = 0;
  }

  // Drops n bytes at the front, reported in *error; the lock is lost.
  FrameStatus skip(size_t n, const char* reason, FrameError* error) {
    *error = {buffer.offset(), n, reason};
    buffer.consume(n);
    probe = 0;
    in_lock = false;
    return FrameStatus::kBad;
  }

  // Returns the `bytes` at the front as a frame, consumed on the next call; the framer is in lock.
  FrameStatus take(size_t bytes, RawFrame* frame) {
    in_lock = true;
    last_frame_bytes = bytes;
    *frame = {buffer.offset(), buffer.data(), bytes};
    pending = bytes;
    return FrameStatus::kFrame;
  }
};

}  // namespace deepnav
