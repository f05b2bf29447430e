#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Core>

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
  std::uint32_t frozen = 0;       // refused: bit-identical to the previous ones (EkfConfig::stuck_after_samples)
  std::uint32_t gate_resets = 0;  // lockout recoveries (EkfConfig::gate_reset_after_us, gate_reset.h)
  std::uint32_t bad_stamps = 0;   // refused: stamped beyond the fusion window ahead of the IMU clock
};

struct SourceHealth {
  SourceCounters counters;
  TimeUs last_accepted_t_us = -1;  // -1: never
  TimeUs last_seen_t_us = -1;      // latest valid sample that reached the gate (accepted or rejected)
  bool last_rejected = false;      // outcome of the latest (in capture time) fused sample, or frozen
  bool last_stamp_bad = false;     // a sample was refused for its stamp since the latest fused one
  double last_test_ratio = 0.0;
  std::uint64_t last_fingerprint = 0;  // sample_fingerprint.h of the latest sample
  int repeats = 0;                     // consecutive samples with that fingerprint
  Eigen::Vector3d last_value = Eigen::Vector3d::Zero();  // measured values of the latest sample
  int smooth_streak = 0;  // consecutive samples each within the reset gate of the one before
  TimeUs last_gate_reset_t_us = -1;
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
  TimeUs startTime() const { return start_us_; }
  void record(NavSource src, FuseStatus previous, FuseStatus now, TimeUs t_us, double test_ratio);
  void countDroppedLate(NavSource src) { ++at(src).counters.dropped_late; }
  void countBadInput(NavSource src) { ++at(src).counters.bad_input; }
  // A sample whose stamp cannot be its capture time (the source's clock jumped ahead): counted as bad
  // input and as a bad stamp; it raises the reject flag until the source's next fused sample, without
  // counting towards a gate lockout (the filter never saw it).
  void noteBadStamp(NavSource src) {
    SourceHealth& h = at(src);
    ++h.counters.bad_input;
    ++h.counters.bad_stamps;
    h.last_stamp_bad = true;
  }
  // Notes a sample's fingerprint; true when it is the limit-th (or later) identical one in a row (limit 0:
  // never). Such a sample is counted frozen and raises the reject flag; it does not count as seen, so a
  // frozen source also goes stale after its timeout.
  bool noteFrozen(NavSource src, std::uint64_t fingerprint, int limit);
  // True when the source's latest sample was rejected (or frozen) and none was accepted, nor the
  // source reset, for longer than after_us before t_us (after_us 0: never).
  bool lockedOut(NavSource src, TimeUs t_us, TimeUs after_us) const;
  void noteGateReset(NavSource src, TimeUs t_us);
  // Notes the change of the source's measured values since its previous sample (largest component,
  // angles wrapped by the caller): within `tolerance` extends the smooth streak, else restarts it.
  void noteChange(NavSource src, const Eigen::Vector3d& value, double change, double tolerance);
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
