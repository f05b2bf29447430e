#include "tools/sim/sensors/dvl_ping_timing.h"

#include <algorithm>
#include <cmath>

namespace deepnav::sim {

namespace {
// Channel due times are rounded to whole microseconds, so a period of exactly one tick may come out a
// microsecond short: that much slack keeps such a ping due.
constexpr TimeUs kRoundingSlack_us = 2;
}  // namespace

double DvlPingTiming::period_s(double slant_range_m, double max_ping_rate_hz, double processing_s) {
  return std::max(1.0 / max_ping_rate_hz, 2.0 * slant_range_m / kDvlSoundSpeed_mps + processing_s);
}

void DvlPingTiming::pinged(TimeUs t_us, double slant_range_m) {
  if (!enabled()) return;
  const double period = period_s(slant_range_m, max_ping_rate_hz_, processing_s_);
  next_ping_us_ = t_us + static_cast<TimeUs>(std::llround(period * 1e6)) - kRoundingSlack_us;
}

}  // namespace deepnav::sim
