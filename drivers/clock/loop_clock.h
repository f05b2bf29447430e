#pragma once
#include <cmath>

#include "nav/types/time.h"

namespace deepnav {

// The loop's clock against the monotonic clock: t_loop = t_mono + offset at speed 1 (the vehicle: offset 0;
// a replay: the recording's clock mapped onto now), or, for a replay faster than real time (the soak),
// t_loop = anchor_loop + speed * (t_mono - anchor_mono). The replay driver and the loop share one mapping,
// so the loop ticks on the recording's clock whatever the speed.
struct LoopClock {
  TimeUs offset_us = 0;
  double speed = 1.0;
  TimeUs anchor_mono_us = 0;  // where the two clocks meet when speed != 1

  static LoopClock at(TimeUs offset_us, double speed, TimeUs anchor_mono_us) {
    return LoopClock{offset_us, speed, anchor_mono_us};
  }
  TimeUs toLoop(TimeUs mono_us) const {
    if (speed == 1.0) return mono_us + offset_us;
    return anchor_mono_us + offset_us + static_cast<TimeUs>(std::llround(speed * static_cast<double>(mono_us - anchor_mono_us)));
  }
  TimeUs toMono(TimeUs loop_us) const {
    if (speed == 1.0) return loop_us - offset_us;
    return anchor_mono_us + static_cast<TimeUs>(std::llround(static_cast<double>(loop_us - offset_us - anchor_mono_us) / speed));
  }
};

}  // namespace deepnav
