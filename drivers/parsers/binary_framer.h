#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/parsers/binary_framer_core.h"
#include "drivers/parsers/frame_result.h"
#include "drivers/parsers/later_frame_scan.h"

namespace deepnav {

// What the binary framers (Pd0Framer, XbusFramer) share around their own header and frame checks: the
// input calls, and the steps of next() that follow the check of the frame at the front, with the scans
// of later_frame_scan.h over the held bytes. A framer derives from BinaryFramer<Framer, kFirstByte>
// (kFirstByte: the first byte of every header) and gives headerAt(at) and checkAt(at, &bytes, &reason).
template <class Framer, uint8_t kFirstByte>
class BinaryFramer {
 public:
  size_t push(const uint8_t* data, size_t n) { return core_.push(data, n); }
  // No byte will follow (end of a file): what is held is framed without waiting.
  void endOfInput() { core_.end_of_input = true; }
  // The bytes come from a file, not a live line: waiting for later bytes costs no latency, so a
  // frame in lock whose refusal depends on bytes not yet held waits for them too.
  void waitForCertainty() { core_.wait_for_certainty = true; }

 protected:
  // The checksum-valid frame of `bytes` at the front. It may still be a false header whose checksum
  // happened to hold (1 in 256 for an 8-bit sum, e.g. a frame cut short whose length then runs into the
  // next one): when `scan`, it is refused (overrun_reason) if a frame starting inside it is valid, runs
  // past its end and is followed by a header (or by the end of the input). Out of lock (after skipped
  // bytes) the answer waits while such a later frame is incomplete (at most one maximal frame); in lock
  // the frame is taken unless the refusal is certain, so the steady state of a live line never waits (a
  // file, waitForCertainty(), always waits). The scan is a memchr over the frame: a few percent of its cost.
  FrameStatus takeValid(size_t bytes, bool scan, const char* overrun_reason, RawFrame* frame, FrameError* error) {
    const FrameOverrun o = scan ? overrunByLaterFrame(bytes) : FrameOverrun::kNo;
    if (o == FrameOverrun::kYes) return core_.skip(1, overrun_reason, error);
    if (o == FrameOverrun::kNotYetKnown && (!core_.in_lock || core_.wait_for_certainty) && !core_.buffer.full()) {
      return FrameStatus::kNeedMore;
    }
    return core_.take(bytes, frame);
  }

  // An incomplete frame at the front, the input going on and the buffer not full: its header is taken
  // as false (skipped up to there, false_header_reason) when a later complete, valid frame followed by
  // a header is held, else the framer waits for more bytes.
  FrameStatus waitOrSkipFalseHeader(const char* false_header_reason, FrameError* error) {
    // In lock, a frame no longer than the last one cannot hold a later one yet: no probe (steady state).
    if (core_.in_lock && core_.buffer.size() <= core_.last_frame_bytes) return FrameStatus::kNeedMore;
    if (const size_t at = laterValidFrame(); at > 0) return core_.skip(at, false_header_reason, error);
    return FrameStatus::kNeedMore;
  }

  BinaryFramerCore core_;

 private:
  const Framer& framer() const { return static_cast<const Framer&>(*this); }
  auto header() const {
    return [this](size_t at) { return framer().headerAt(at); };
  }
  auto check() const {
    return [this](size_t at, size_t* bytes) {
      const char* why = "";
      return framer().checkAt(at, bytes, &why);
    };
  }
  size_t laterValidFrame() {
    return deepnav::laterValidFrame(core_.buffer.data(), core_.buffer.size(), kFirstByte, &core_.probe, header(),
                                    check());
  }
  FrameOverrun overrunByLaterFrame(size_t frame_bytes) const {
    return deepnav::overrunByLaterFrame(core_.buffer.data(), core_.buffer.size(), frame_bytes, kFirstByte,
                                        core_.end_of_input, header(), check());
  }
};

}  // namespace deepnav
