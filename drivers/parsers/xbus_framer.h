#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/binary_framer.h"
#include "drivers/parsers/frame_result.h"

namespace deepnav {

// Finds Xsens Xbus messages in a byte stream: preamble 0xFA, bus ID (0xFF), message ID, length byte
// (0xFF: a 2-byte big-endian extended length follows), payload, checksum such that the 8-bit sum of
// every byte after the preamble is zero. Failed frames are reported and the search restarts one byte
// after the preamble. While a message is incomplete, the bytes already held are probed for a later
// complete, checksum-valid message followed by a preamble and bus ID: one is taken as proof that the
// first preamble was false (a live line then does not wait for bytes of later messages). After
// endOfInput() an incomplete message is dropped one byte at a time so the messages inside it are found.
// After skipped bytes, a checksum-valid message (an 8-bit sum passes 1 in 256 false ones) is refused
// when a valid message starting inside it runs past its end and is followed by a preamble and bus ID.
class XbusFramer : public BinaryFramer<XbusFramer, 0xFA> {
 public:
  bool init(size_t max_payload_bytes);
  FrameStatus next(RawFrame* frame, FrameError* error);

 private:
  friend class BinaryFramer<XbusFramer, 0xFA>;
  using Check = FrameCheck;
  // The candidate message whose preamble is `at` bytes into the buffer.
  Check checkAt(size_t at, size_t* frame_bytes, const char** reason) const;
  bool headerAt(size_t at) const;

  size_t max_payload_ = 0;
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
