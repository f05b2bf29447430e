#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include "nav/types/time.h"

namespace deepnav {

// Pairs the frames of two free-running or triggered cameras by timestamp. Each side keeps a few
// frames waiting for their partner; a frame is paired with the other side's waiting frame nearest in
// time if the two are at most `tolerance_us` apart. Frames that can no longer find a partner (the other
// side has moved past them) are handed back as dropped, so the driver can count them and recycle their
// buffers. With software triggers each frame also carries the tick of the trigger it answers
// (TriggerTracker): frames then pair only with the same tick (and still within tolerance), so the
// frames of two triggers are never paired however late one arrives. Pure logic on opaque handles: no
// clock, no allocation.
class FramePairer {
 public:
  static constexpr int kMaxPending = 8;

  struct Frame {
    TimeUs t_us = 0;  // the timestamp pairs are matched on
    int handle = -1;  // the caller's buffer index
    std::int64_t tick = -1;  // trigger tick the frame answers; -1: unknown (pair by time only)
  };
  struct Result {
    bool paired = false;
    Frame left, right;
    std::array<Frame, 2 * kMaxPending + 1> dropped{};
    int dropped_count = 0;
  };

  explicit FramePairer(TimeUs tolerance_us = 0) : tolerance_us_(tolerance_us) {}
  void setTolerance(TimeUs tolerance_us) { tolerance_us_ = tolerance_us; }
  // Frames kept waiting per side, at most kMaxPending. Each holds a driver buffer: keep it well below
  // the driver's buffer count, or the camera runs out of buffers to fill while its partner is away.
  void setMaxPending(int n) { max_pending_ = n < 1 ? 1 : (n > kMaxPending ? kMaxPending : n); }
  TimeUs tolerance() const { return tolerance_us_; }

  // Offers a good frame of side 0 (left) or 1 (right). tick >= 0: the software trigger it answers
  // (ticks grow on each side); a pair then needs equal ticks and times within tolerance.
  Result offer(int side, TimeUs t_us, int handle, std::int64_t tick = -1);

  // Hands back every waiting frame of one side (camera lost or stopped); returns how many.
  int flush(int side, std::array<Frame, kMaxPending>* out);
  int pending(int side) const { return count_[static_cast<std::size_t>(side)]; }

 private:
  void removeAt(int side, int index);
  // Keeps `self` waiting on its side; a full side first hands its oldest frame to r->dropped.
  void keepWaiting(int side, const Frame& self, Result* r);
  void dropOlderThan(int side, TimeUs t_us, Result* r);
  void dropTicksBelow(int side, std::int64_t tick, Result* r);
  // Moves every waiting frame of one side that `drop` selects into r->dropped, keeping the others' order.
  template <typename Pred>
  void dropIf(int side, Result* r, Pred drop) {
    auto& p = pending_[static_cast<std::size_t>(side)];
    for (int i = 0; i < count_[static_cast<std::size_t>(side)];) {
      if (drop(p[static_cast<std::size_t>(i)])) {
        r->dropped[static_cast<std::size_t>(r->dropped_count++)] = p[static_cast<std::size_t>(i)];
        removeAt(side, i);
      } else {
        ++i;
      }
    }
  }
  Result offerTicked(int side, const Frame& self);

  TimeUs tolerance_us_;
  int max_pending_ = kMaxPending;
  std::array<std::array<Frame, kMaxPending>, 2> pending_{};
  std::array<int, 2> count_{0, 0};
};

}  // namespace deepnav
