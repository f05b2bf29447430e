#pragma once
#include <cstddef>
#include <cstdint>

namespace deepnav {

// What a framer returns on each call to next().
enum class FrameStatus {
  kNeedMore,  // no complete frame in the buffered bytes: push more
  kFrame,     // *frame holds one complete, checksum-valid frame
  kBad,       // *error says which bytes were skipped and why; call next() again
};

// One complete frame; data stays valid until the next call to next() or push().
struct RawFrame {
  uint64_t offset = 0;  // stream offset of the frame's first byte
  const uint8_t* data = nullptr;
  size_t size = 0;
};

// Bytes skipped while resynchronising: a frame that failed its checks, or noise between frames.
struct FrameError {
  uint64_t offset = 0;   // stream offset of the first skipped byte
  size_t skipped = 0;    // bytes dropped
  const char* reason = "";
};

}  // namespace deepnav
