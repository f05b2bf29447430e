#pragma once
#include <cstdint>

#include "drivers/outputs/nav_output.h"
#include "nav/types/loop_stats.h"

namespace deepnav {

// What the health monitor samples from the running service, once per health window.
struct HealthSample {
  LoopStats loop;
  std::uint64_t recorder_drops = 0;
  std::uint64_t recorder_failures = 0;
  std::uint64_t inputs_refused = 0;
  std::uint64_t vision_failures = 0;  // stereo pairs failed by a throwing vision stage (cumulative)
  std::uint32_t faults = 0;  // of the latest solution
  bool solution_finite = true;
};

// Turns successive samples into the health bits of the last window and the watchdog decision. The nav
// loop is healthy when it ticked during the window and its solution is finite: only then is systemd's
// watchdog fed, so a stalled or broken loop gets the service restarted. Sensor faults are reported but
// do not starve the watchdog (a restart does not bring a DVL back).
class HealthMonitor {
 public:
  // Evaluates the window since the previous call (the first call only sets the reference).
  std::uint32_t update(const HealthSample& now);
  std::uint32_t bits() const { return bits_; }
  bool healthy() const { return (bits_ & (kHealthLoopStalled | kHealthNotFinite)) == 0; }

 private:
  HealthSample last_;
  bool has_last_ = false;
  std::uint32_t bits_ = 0;
};

// The cumulative loop and buffer counters of a sample, as the outputs carry them.
void fillLoopCounters(const HealthSample& sample, NavCounters* counters);

// Index of a task in the loop statistics, -1 when absent.
int taskIndex(const LoopStats& stats, const char* name);

}  // namespace deepnav
