#pragma once
#include "nav/types/time.h"

namespace deepnav::sim {

// Nominal sound speed for the DVL's travel times, m/s.
constexpr double kDvlSoundSpeed_mps = 1500.0;

// When a DVL can ping again: each ping waits for the echo of its longest beam (two-way travel time) and
// for its processing, and never comes sooner than the instrument's maximum ping rate allows:
//   period = max(1 / max_ping_rate_hz, 2 slant_range / c + processing).
// Searching for the bottom (no beam locked) the instrument listens over its whole window, so the caller
// passes the window's longest slant range then. The channel ticks at its rate; a ping is due at the
// first tick at or after last ping + period, so the rate is quantised to the channel's ticks.
class DvlPingTiming {
 public:
  void init(double max_ping_rate_hz, double processing_s) {
    max_ping_rate_hz_ = max_ping_rate_hz;
    processing_s_ = processing_s;
    next_ping_us_ = 0;
  }
  bool enabled() const { return max_ping_rate_hz_ > 0.0; }
  static double period_s(double slant_range_m, double max_ping_rate_hz, double processing_s);
  // Whether a ping is due at t_us (always when disabled).
  bool due(TimeUs t_us) const { return !enabled() || t_us >= next_ping_us_; }
  // A ping went out at t_us with the given longest slant range: schedules the next one.
  void pinged(TimeUs t_us, double slant_range_m);

 private:
  double max_ping_rate_hz_ = 0.0;
  double processing_s_ = 0.0;
  TimeUs next_ping_us_ = 0;
};

}  // namespace deepnav::sim
