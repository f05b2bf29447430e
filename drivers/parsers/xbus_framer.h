#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/frame_result.h"
#include "drivers/parsers/stream_buffer.h"

namespace deepnav {

// Finds Xsens Xbus messages in a byte stream: preamble 0xFA, bus ID (0xFF), message ID, length byte
// (0xFF: a 2-byte big-endian extended length follows), payload, checksum such that the 8-bit sum of
// every byte after the preamble is zero. Failed frames are reported and the search restarts one byte
// after the preamble.
class XbusFramer {
 public:
  bool init(size_t max_payload_bytes);
  size_t push(const uint8_t* data, size_t n) { return flushPending(), buffer_.append(data, n); }
  FrameStatus next(RawFrame* frame, FrameError* error);

 private:
  void flushPending();
  FrameStatus skip(size_t n, const char* reason, FrameError* error);

  StreamBuffer buffer_;
  size_t max_payload_ = 0;
  size_t pending_ = 0;
};

// A framed Xbus message split into its parts (the frame as returned by XbusFramer).
struct XbusMessage {
  uint8_t bus_id = 0;
  uint8_t message_id = 0;
  const uint8_t* payload = nullptr;
  size_t payload_size = 0;
};
bool splitXbusFrame(const uint8_t* frame, size_t size, XbusMessage* message);

}  // namespace deepnav
