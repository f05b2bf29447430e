#include "tools/sim/sensor_timing.h"

#include <algorithm>
#include <cmath>

namespace deepnav::sim {

TimeUs StreamTiming::shift_us(TimeUs t_us) const {
  const double shift_us = (clock_offset_ms + latency_ms) * 1e3 + clock_drift_ppm * 1e-6 * static_cast<double>(t_us);
  return static_cast<TimeUs>(std::llround(shift_us));
}

bool TimingConfig::active() const {
  return std::any_of(streams.begin(), streams.end(), [](const StreamTiming& s) { return s.active(); });
}

TimeUs TimingConfig::maxAdvance_us(TimeUs end_us) const {
  TimeUs advance_us = 0;
  for (const StreamTiming& s : streams) {
    if (!s.active()) continue;
    advance_us = std::max({advance_us, -s.shift_us(0), -s.shift_us(end_us)});
  }
  return advance_us;
}

}  // namespace deepnav::sim
