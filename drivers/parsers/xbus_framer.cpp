#include "drivers/parsers/xbus_framer.h"

#include <algorithm>
#include <cstring>

#include "drivers/parsers/byte_order.h"

namespace deepnav {
namespace {

constexpr uint8_t kPreamble = 0xFA;
constexpr uint8_t kMasterBusId = 0xFF;

}  // namespace

bool XbusFramer::init(size_t max_payload_bytes) {
  if (max_payload_bytes == 0 || max_payload_bytes > 65535) return false;
  max_payload_ = max_payload_bytes;
  return core_.init(max_payload_bytes + 7 + 4096);
}

bool XbusFramer::headerAt(size_t at) const {
  const uint8_t* d = core_.buffer.data();
  return at + 1 < core_.buffer.size() && d[at] == kPreamble && d[at + 1] == kMasterBusId;
}

XbusFramer::Check XbusFramer::checkAt(size_t at, size_t* frame_bytes, const char** reason) const {
  const uint8_t* d = core_.buffer.data() + at;
  const size_t avail = core_.buffer.size() - at;
  if (avail >= 2 && d[1] != kMasterBusId) {
    *reason = "Xbus bus ID is not 0xFF";
    return Check::kBad;
  }
  if (avail < 4) return Check::kIncomplete;
  size_t header = 4;
  size_t length = d[3];
  if (length == 0xFF) {
    if (avail < 6) return Check::kIncomplete;
    length = readBe16(d + 4);
    header = 6;
  }
  if (length > max_payload_) {
    *reason = "Xbus length out of range";
    return Check::kBad;
  }
  const size_t total = header + length + 1;
  *frame_bytes = total;
  if (avail < total) return Check::kIncomplete;
  uint8_t sum = 0;
  for (size_t i = 1; i < total; ++i) sum = uint8_t(sum + d[i]);
  if (sum != 0) {
    *reason = "Xbus checksum mismatch";
    return Check::kBad;
  }
  return Check::kValid;
}

FrameStatus XbusFramer::next(RawFrame* frame, FrameError* error) {
  core_.flushPending();
  const uint8_t* d = core_.buffer.data();
  const size_t size = core_.buffer.size();
  size_t start = 0;
  while (start < size && d[start] != kPreamble) ++start;
  if (start > 0) return core_.skip(start, "no Xbus preamble (0xFA)", error);
  if (size == 0) return FrameStatus::kNeedMore;
  size_t bytes = 0;
  const char* why = "";
  switch (checkAt(0, &bytes, &why)) {
    case Check::kBad: return core_.skip(1, why, error);
    case Check::kValid:
      {
        // In lock on a live line only a certain refusal counts, and it needs a later message ending past
        // this one and the next preamble: with fewer bytes held there is nothing to scan.
        const bool scan = !core_.in_lock || core_.wait_for_certainty || core_.end_of_input || size > bytes + 2;
        return takeValid(bytes, scan, "Xbus message overrun by a later valid message", frame, error);
      }
    case Check::kIncomplete: break;
  }
  if (core_.end_of_input) return core_.skip(1, "Xbus message cut short by the end of the input", error);
  if (core_.buffer.full()) return core_.skip(1, "Xbus message larger than the buffer", error);
  return waitOrSkipFalseHeader("Xbus length runs over a later valid message", error);
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
