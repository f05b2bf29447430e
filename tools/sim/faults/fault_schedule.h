#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "nav/types/time.h"
#include "tools/sim/faults/fault_spec.h"
#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// What the schedule does to one sample.
struct FaultDecision {
  bool drop = false;
  bool stuck = false;
  bool garbage = false;        // replace the content by random values (garbage_values.h)
  double outlier_sigma = 0.0;  // > 0: add +-outlier_sigma * noise sigma to every component
  TimeUs jitter_us = 0;        // added to the stamp (time_jitter): the sample is delivered at its stamp
  TimeUs clock_offset_us = 0;  // added to the stamp (clock_jump): the sample is delivered when it arrives
};

// The scenario's fault list, queried per sample. Random choices (hit or not, jitter) come from the
// caller's fault RNG, separate from the sensor noise RNG: the clean part of a stream is the same with or
// without faults.
class FaultSchedule {
 public:
  bool init(const std::vector<FaultSpec>& faults, std::string* error);
  // index: the sample's index in its stream (slow keeps index % divisor == 0).
  FaultDecision decide(SimStream stream, double t_s, std::uint64_t index, NormalRng& rng) const;
  // Largest |stamp shift| any fault can add: the merger holds events back this long to stay time-ordered.
  TimeUs maxJitter_us() const { return max_jitter_us_; }

 private:
  std::vector<FaultSpec> faults_;
  TimeUs max_jitter_us_ = 0;
};

}  // namespace deepnav::sim
