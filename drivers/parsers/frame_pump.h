#pragma once
#include "drivers/parsers/frame_result.h"

namespace deepnav {

// Drives a framer (Pd0Framer, XbusFramer, LineFramer) over an input: each frame goes to
// on_frame(const RawFrame&), each skipped range to on_bad(const FrameError&); when the framer needs
// bytes, feed(framer) pushes some and returns true, or returns false: the input has no more for now,
// and the call returns.
template <class Framer, class Feed, class OnFrame, class OnBad>
void frameWhileFed(Framer* framer, Feed feed, OnFrame on_frame, OnBad on_bad) {
  while (true) {
    RawFrame f;
    FrameError e;
    const FrameStatus st = framer->next(&f, &e);
    if (st == FrameStatus::kFrame) {
      on_frame(f);
    } else if (st == FrameStatus::kBad) {
      on_bad(e);
    } else if (!feed(framer)) {
      return;
    }
  }
}

// What the framer still holds once the input has ended (endOfInput()), framed without waiting.
template <class Framer, class OnFrame, class OnBad>
void frameTheRest(Framer* framer, OnFrame on_frame, OnBad on_bad) {
  framer->endOfInput();
  frameWhileFed(framer, [](Framer*) { return false; }, on_frame, on_bad);
}

// A whole input (a file): frameWhileFed() until feed() has no more, then frameTheRest().
template <class Framer, class Feed, class OnFrame, class OnBad>
void frameToEnd(Framer* framer, Feed feed, OnFrame on_frame, OnBad on_bad) {
  frameWhileFed(framer, feed, on_frame, on_bad);
  frameTheRest(framer, on_frame, on_bad);
}

}  // namespace deepnav
