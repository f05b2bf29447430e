#pragma once
#include <array>

#include "nav/types/time.h"
#include "tools/sim/sim_stream.h"

namespace deepnav::sim {

// How one stream's stamps differ from the instant its content was measured (scenario `timing.<stream>`):
//   stamp = t + clock_offset + clock_drift * t + latency,
// t the true measurement instant (trajectory time). The content stays at t, as with the clock_jump fault.
// latency: the stamp is taken when the message arrives, later than the measurement; clock offset and
// drift: the sensor's clock against the vehicle's. The camera's offset is the camera-IMU time offset.
struct StreamTiming {
  double latency_ms = 0.0;
  double clock_offset_ms = 0.0;
  double clock_drift_ppm = 0.0;

  bool active() const { return latency_ms != 0.0 || clock_offset_ms != 0.0 || clock_drift_ppm != 0.0; }
  // The stamp shift at true time t_us, rounded to the microsecond.
  TimeUs shift_us(TimeUs t_us) const;
  bool operator==(const StreamTiming&) const = default;
};

// Scenario key `timing`: one entry per SimStream (the ground-truth entry stays zero: truth is exact).
struct TimingConfig {
  std::array<StreamTiming, kSimStreamCount> streams{};

  bool active() const;
  StreamTiming& of(SimStream s) { return streams[static_cast<int>(s)]; }
  const StreamTiming& of(SimStream s) const { return streams[static_cast<int>(s)]; }
  // Largest amount any stamp in [0, end_us] moves EARLIER than its instant (>= 0): the merger must hold
  // events back this long so the output stays time-ordered. The shift is linear in t, so its minimum
  // is at one of the ends.
  TimeUs maxAdvance_us(TimeUs end_us) const;
  bool operator==(const TimingConfig&) const = default;
};

}  // namespace deepnav::sim
