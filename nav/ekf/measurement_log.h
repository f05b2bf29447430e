#pragma once
#include <cstdint>
#include <variant>
#include <vector>

#include "nav/ekf/ekf_measurements.h"
#include "nav/ekf/fuse_result.h"
#include "nav/ekf/mag_disturbance.h"
#include "nav/types/attitude_sample.h"
#include "nav/types/depth_sample.h"
#include "nav/types/dvl_sample.h"
#include "nav/types/heading_sample.h"

namespace deepnav {

// Clone bookkeeping travels through the log like a measurement, so that a replay recreates it.
struct CloneRequest {
  TimeUs t_us = 0;
  std::uint32_t id = 0;
};
struct CloneRelease {
  TimeUs t_us = 0;
  std::uint32_t id = 0;
};
// A lockout recovery (gate_reset.h) travels the same way, just before the sample that triggered it.
struct GateReset {
  TimeUs t_us = 0;
  NavSource source = kSrcCount;
};

using MeasurementPayload = std::variant<DvlSample, DepthSample, HeadingSample, AttitudeSample, PoseMeasurement,
                                        RelativePoseMeasurement, CloneRequest, CloneRelease, GateReset>;

struct LoggedMeasurement {
  TimeUs t_us = 0;
  std::uint64_t seq = 0;      // arrival order, breaks ties between equal times
  MeasurementPayload payload;
  FuseStatus outcome = FuseStatus::kQueued;  // current outcome; revised by a replay
  double test_ratio = 0.0;
  MagAction mag_action = MagAction::kUndecided;  // compass only: the detector's decision, kept for re-fusion
};

// Measurements inside the delay window, sorted by (t_us, seq): the ones already fused (for re-fusion after
// a rewind) and the ones newer than the last IMU sample (queued). Capacity reserved once in allocate().
class MeasurementLog {
 public:
  bool allocate(int capacity);
  void clear() { events_.clear(); }
  int size() const { return static_cast<int>(events_.size()); }
  bool full() const { return events_.size() == events_.capacity(); }
  // Inserts after every entry with t <= e.t_us; returns its index, or -1 when full.
  int insert(const LoggedMeasurement& e);
  void popOldest();
  LoggedMeasurement& at(int i) { return events_[static_cast<std::size_t>(i)]; }
  const LoggedMeasurement& at(int i) const { return events_[static_cast<std::size_t>(i)]; }
  // Index of the first entry with t > t_us (size() when none).
  int firstAfter(TimeUs t_us) const;
  // Index of the first entry with t >= t_us (size() when none).
  int firstAtOrAfter(TimeUs t_us) const;

 private:
  std::vector<LoggedMeasurement> events_;
};

}  // namespace deepnav
