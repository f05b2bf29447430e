#include "drivers/parsers/xbus_framer.h"

#include "drivers/parsers/byte_order.h"

namespace deepnav {
namespace {

constexpr uint8_t kPreamble = 0xFA;
constexpr uint8_t kMasterBusId = 0xFF;

}  // namespace

bool XbusFramer::init(size_t max_payload_bytes) {
  if (max_payload_bytes == 0 || max_payload_bytes > 65535) return false;
  max_payload_ = max_payload_bytes;
  pending_ = 0;
  return buffer_.init(max_payload_bytes + 7 + 4096);
}

void XbusFramer::flushPending() {
  buffer_.consume(pending_);
  pending_ = 0;
}

FrameStatus XbusFramer::skip(size_t n, const char* reason, FrameError* error) {
  *error = {buffer_.offset(), n, reason};
  buffer_.consume(n);
  return FrameStatus::kBad;
}

FrameStatus XbusFramer::next(RawFrame* frame, FrameError* error) {
  flushPending();
  const uint8_t* d = buffer_.data();
  const size_t size = buffer_.size();
  size_t start = 0;
  while (start < size && d[start] != kPreamble) ++start;
  if (start > 0) return skip(start, "no Xbus preamble (0xFA)", error);
  if (size < 4) return FrameStatus::kNeedMore;
  if (d[1] != kMasterBusId) return skip(1, "Xbus bus ID is not 0xFF", error);
  size_t header = 4;
  size_t length = d[3];
  if (length == 0xFF) {
    if (size < 6) return FrameStatus::kNeedMore;
    length = readBe16(d + 4);
    header = 6;
  }
  if (length > max_payload_) return skip(1, "Xbus length out of range", error);
  const size_t total = header + length + 1;
  if (size < total) return FrameStatus::kNeedMore;
  uint8_t sum = 0;
  for (size_t i = 1; i < total; ++i) sum = uint8_t(sum + d[i]);
  if (sum != 0) return skip(1, "Xbus checksum mismatch", error);
  *frame = {buffer_.offset(), d, total};
  pending_ = total;
  return FrameStatus::kFrame;
}

bool splitXbusFrame(const uint8_t* d, size_t size, XbusMessage* m) {
  if (size < 5 || d[0] != kPreamble) return false;
  size_t header = 4, length = d[3];
  if (length == 0xFF) {
    if (size < 7) return false;
    header = 6;
    length = readBe16(d + 4);
  }
  if (header + length + 1 != size) return false;
  *m = {d[1], d[2], d + header, length};
  return true;
}

}  // namespace deepnav
