#pragma once
#include <array>
#include <cstdint>

#include "nav/ekf/fuse_result.h"
#include "nav/types/nav_solution.h"
#include "nav/types/time.h"

namespace deepnav {

struct EkfConfig;

struct SourceCounters {
  std::uint32_t accepted = 0;
  std::uint32_t rejected = 0;
  std::uint32_t dropped_late = 0;
  std::uint32_t bad_input = 0;
};

struct SourceHealth {
  SourceCounters counters;
  TimeUs last_accepted_t_us = -1;  // -1: never
  TimeUs last_seen_t_us = -1;      // latest valid sample that reached the gate (accepted or rejected)
  bool last_rejected = false;      // outcome of the latest (in capture time) fused sample
  double last_test_ratio = 0.0;
};

// Per-source counters, stale and reject flags (PX4 ekf2 style). A source is stale when its timeout is
// non-zero and no valid sample reached the gate for longer than the timeout (counted from start() if
// never): stale means "no data"; data that arrives but fails the gate raises the reject flag instead.
// Outcomes can be revised when a late measurement forces re-fusion: record() undoes the previous
// outcome of that sample, so the counters always describe the current estimate.
class SourceHealthMonitor {
 public:
  void configure(const EkfConfig& config);
  void start(TimeUs t_us);  // at alignment or reset; keeps the counters
  void record(NavSource src, FuseStatus previous, FuseStatus now, TimeUs t_us, double test_ratio);
  void countDroppedLate(NavSource src) { ++at(src).counters.dropped_late; }
  void countBadInput(NavSource src) { ++at(src).counters.bad_input; }
  bool isStale(NavSource src, TimeUs now_us) const;
  bool acceptedWithin(NavSource src, TimeUs now_us, TimeUs window_us) const;
  std::uint32_t faultBits(TimeUs now_us) const;  // staleBit() | rejectBit() of every source
  const SourceHealth& source(NavSource src) const { return sources_[static_cast<std::size_t>(src)]; }
  std::uint32_t rejectedTotal() const;
  std::uint32_t droppedLateTotal() const;

 private:
  SourceHealth& at(NavSource src) { return sources_[static_cast<std::size_t>(src)]; }

  std::array<SourceHealth, kSrcCount> sources_{};
  std::array<TimeUs, kSrcCount> timeout_us_{};
  TimeUs start_us_ = 0;
};

}  // namespace deepnav
