#include "drivers/camera/frame_pairer.h"

namespace deepnav {

void FramePairer::removeAt(int side, int index) {
  auto& p = pending_[static_cast<std::size_t>(side)];
  int& n = count_[static_cast<std::size_t>(side)];
  for (int i = index; i + 1 < n; ++i) p[static_cast<std::size_t>(i)] = p[static_cast<std::size_t>(i + 1)];
  --n;
}

void FramePairer::keepWaiting(int side, const Frame& self, Result* r) {
  auto& mine = pending_[static_cast<std::size_t>(side)];
  if (count_[static_cast<std::size_t>(side)] >= max_pending_) {
    r->dropped[static_cast<std::size_t>(r->dropped_count++)] = mine[0];
    removeAt(side, 0);
  }
  mine[static_cast<std::size_t>(count_[static_cast<std::size_t>(side)]++)] = self;
}

void FramePairer::dropOlderThan(int side, TimeUs t_us, Result* r) {
  dropIf(side, r, [t_us](const Frame& f) { return f.t_us < t_us; });
}

void FramePairer::dropTicksBelow(int side, std::int64_t tick, Result* r) {
  dropIf(side, r, [tick](const Frame& f) { return f.tick < tick; });
}

// Pairing by trigger tick: only the other side's frame of the same tick is a partner, and only within
// tolerance (a pair of one trigger whose frames are far apart in time is not synchronised: both go).
FramePairer::Result FramePairer::offerTicked(int side, const Frame& self) {
  Result r;
  const int other = 1 - side;
  auto& op = pending_[static_cast<std::size_t>(other)];
  // Ticks grow on each side: the other side's waiting frames of earlier ticks can never pair now.
  dropTicksBelow(other, self.tick, &r);
  for (int i = 0; i < count_[static_cast<std::size_t>(other)]; ++i) {
    const Frame partner = op[static_cast<std::size_t>(i)];
    if (partner.tick != self.tick) continue;
    removeAt(other, i);
    const TimeUs d = partner.t_us - self.t_us;
    if ((d < 0 ? -d : d) > tolerance_us_) {
      r.dropped[static_cast<std::size_t>(r.dropped_count++)] = partner;
      r.dropped[static_cast<std::size_t>(r.dropped_count++)] = self;
      return r;
    }
    r.paired = true;
    r.left = side == 0 ? self : partner;
    r.right = side == 0 ? partner : self;
    dropTicksBelow(side, self.tick, &r);
    return r;
  }
  // The other side is already past this tick (its waiting frames are later): no partner will come.
  if (count_[static_cast<std::size_t>(other)] > 0) {
    r.dropped[static_cast<std::size_t>(r.dropped_count++)] = self;
    return r;
  }
  keepWaiting(side, self, &r);
  return r;
}

FramePairer::Result FramePairer::offer(int side, TimeUs t_us, int handle, std::int64_t tick) {
  if (tick >= 0) return offerTicked(side, Frame{t_us, handle, tick});
  Result r;
  const int other = 1 - side;
  const auto& op = pending_[static_cast<std::size_t>(other)];
  int best = -1;
  TimeUs best_dt = 0;
  for (int i = 0; i < count_[static_cast<std::size_t>(other)]; ++i) {
    const TimeUs d = op[static_cast<std::size_t>(i)].t_us - t_us;
    const TimeUs dt = d < 0 ? -d : d;
    if (dt <= tolerance_us_ && (best < 0 || dt < best_dt)) {
      best = i;
      best_dt = dt;
    }
  }
  const Frame self{t_us, handle};
  if (best >= 0) {
    const Frame partner = op[static_cast<std::size_t>(best)];
    removeAt(other, best);
    r.paired = true;
    r.left = side == 0 ? self : partner;
    r.right = side == 0 ? partner : self;
    // Times grow on each side: waiting frames older than this pair can no longer be matched.
    dropOlderThan(other, partner.t_us, &r);
    dropOlderThan(side, partner.t_us - tolerance_us_, &r);
    return r;
  }
  // No partner yet. The other side's frames older than t - tolerance can never match this side again.
  dropOlderThan(other, t_us - tolerance_us_, &r);
  keepWaiting(side, self, &r);
  return r;
}

int FramePairer::flush(int side, std::array<Frame, kMaxPending>* out) {
  const int n = count_[static_cast<std::size_t>(side)];
  for (int i = 0; i < n; ++i) (*out)[static_cast<std::size_t>(i)] = pending_[static_cast<std::size_t>(side)][static_cast<std::size_t>(i)];
  count_[static_cast<std::size_t>(side)] = 0;
  return n;
}

}  // namespace deepnav
