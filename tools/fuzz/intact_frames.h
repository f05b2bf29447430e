// The property every stream harness checks besides the sanitizers (issue 21): intact frames placed after
// arbitrary bytes all come out of the framer and decoder, at their offsets, byte for byte. The fuzzer's
// input is the junk; the harness appends known-good frames built by tests/support/sensor_frames.h (no
// capture needed), runs the stream to its end and aborts when one of them is missing.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/parsers/frame_pump.h"
#include "drivers/parsers/frame_result.h"

namespace deepnav::fuzz {

class IntactFrames {
 public:
  // `frames[i]` as written on the line; `expected[i]` is what the framer must deliver for it (the
  // frame itself for binary protocols, the line without its terminator for text ones).
  IntactFrames(const uint8_t* junk, size_t n, const std::vector<std::string>& frames, const std::vector<std::string>& expected)
      : stream_(junk, junk + n) {
    for (size_t i = 0; i < frames.size(); ++i) {
      placed_.push_back({stream_.size(), expected[i], false});
      stream_.insert(stream_.end(), frames[i].begin(), frames[i].end());
    }
  }
  const std::vector<uint8_t>& stream() const { return stream_; }
  std::string_view text() const { return {reinterpret_cast<const char*>(stream_.data()), stream_.size()}; }

  // A frame that passed every check of the harness's protocol.
  void delivered(uint64_t offset, const uint8_t* data, size_t size) {
    const std::string_view got(reinterpret_cast<const char*>(data), size);
    for (Placed& p : placed_) p.found = p.found || (offset == p.offset && got == p.expected);
  }
  // A frame the framer returned (checksum-valid), decoded or not. One that starts in the junk and ends
  // exactly where an intact frame starts or the stream ends (the junk ended with a header whose length
  // and checksum happen to hold) may cover intact frames: no framer can tell it from a real frame.
  // One that ends inside an intact frame is not excused.
  void framed(uint64_t offset, size_t size) {
    const uint64_t end = offset + size;
    bool at_boundary = end == stream_.size();
    for (const Placed& p : placed_) at_boundary = at_boundary || end == p.offset;
    if (!at_boundary) return;
    for (Placed& p : placed_) p.found = p.found || (offset < p.offset && end > p.offset);
  }
  void delivered(uint64_t offset, std::string_view s) { delivered(offset, reinterpret_cast<const uint8_t*>(s.data()), s.size()); }

  // Aborts (a libFuzzer finding) when an intact frame was not delivered.
  void verify(const char* format) const {
    for (const Placed& p : placed_) {
      if (p.found) continue;
      std::fprintf(stderr, "%s: the intact frame at byte %zu (after %zu bytes of junk) was not decoded\n", format, p.offset,
                   placed_[0].offset);
      std::abort();
    }
  }

 private:
  struct Placed {
    size_t offset;
    std::string expected;
    bool found;
  };
  std::vector<uint8_t> stream_;
  std::vector<Placed> placed_;
};

// Runs `bytes` through `framer` as `deepnav decode` runs a file: pushed as they fit, then the end of
// the input (endOfInput()); on_frame(RawFrame) for each frame. The binary framers are told to wait
// for certainty (waitForCertainty()) as `deepnav decode` does; on a live line a frame in lock whose
// refusal needs bytes not yet arrived is taken (no latency in the steady state), so the exact property
// is checked on whole inputs. The harnesses feed the input in uneven pieces too, for the sanitizers.
template <typename Framer, typename OnFrame>
void frameToEnd(Framer* framer, const std::vector<uint8_t>& bytes, OnFrame on_frame) {
  size_t pos = 0;
  const auto feed = [&](Framer* fr) {
    if (pos == bytes.size()) return false;
    pos += fr->push(bytes.data() + pos, bytes.size() - pos);
    return true;
  };
  deepnav::frameToEnd(framer, feed, on_frame, [](const FrameError&) {});
}

inline std::string str(const std::vector<uint8_t>& v) { return {v.begin(), v.end()}; }

}  // namespace deepnav::fuzz
