#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/frame_result.h"
#include "drivers/parsers/stream_buffer.h"

namespace deepnav {

// Finds Teledyne RDI PD0 ensembles in a byte stream. An ensemble starts with the header ID 0x7F 0x7F,
// bytes 2-3 hold its length N (little-endian, without the checksum), byte 5 the number of data types,
// and the 16-bit sum of bytes [0, N) follows at N. A frame whose length is out of range or whose
// checksum fails is reported and the search restarts one byte after its header, so a good ensemble
// that a corrupted length had swallowed is still found.
class Pd0Framer {
 public:
  static constexpr size_t kMinEnsembleBytes = 6;
  // max_ensemble_bytes bounds the length field (and sizes the buffer).
  bool init(size_t max_ensemble_bytes);
  size_t push(const uint8_t* data, size_t n) { return flushPending(), buffer_.append(data, n); }
  FrameStatus next(RawFrame* frame, FrameError* error);

 private:
  void flushPending();
  FrameStatus skip(size_t n, const char* reason, FrameError* error);

  StreamBuffer buffer_;
  size_t max_bytes_ = 0;
  size_t pending_ = 0;  // bytes of the last returned frame, consumed on the next call
};

}  // namespace deepnav
