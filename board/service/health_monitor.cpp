#include "board/service/health_monitor.h"

#include <cstring>

namespace deepnav {
namespace {

std::uint64_t taskOverruns(const LoopStats& s, const char* name) {
  const int i = taskIndex(s, name);
  return i < 0 ? 0 : s.overruns[static_cast<std::size_t>(i)];
}

std::uint32_t faultBits(std::uint32_t faults) {
  std::uint32_t bits = 0;
  for (int k = 0; k < kSrcCount; ++k) {
    const auto src = static_cast<NavSource>(k);
    if (faults & staleBit(src)) bits |= kHealthSensorStale;
    if (faults & rejectBit(src)) bits |= kHealthSensorRejected;
  }
  return bits;
}

}  // namespace

int taskIndex(const LoopStats& stats, const char* name) {
  for (int i = 0; i < stats.task_count; ++i) {
    const char* n = stats.names[static_cast<std::size_t>(i)];
    if (n && std::strcmp(n, name) == 0) return i;
  }
  return -1;
}

std::uint32_t HealthMonitor::update(const HealthSample& now) {
  std::uint32_t bits = faultBits(now.faults);
  if (!now.solution_finite) bits |= kHealthNotFinite;
  if (has_last_) {
    if (now.loop.ticks == last_.loop.ticks) bits |= kHealthLoopStalled;
    if (now.loop.late_ticks > last_.loop.late_ticks) bits |= kHealthLoopLate;
    if (taskOverruns(now.loop, "nav") > taskOverruns(last_.loop, "nav")) bits |= kHealthNavOverrun;
    if (taskOverruns(now.loop, "vision") > taskOverruns(last_.loop, "vision")) bits |= kHealthVisionOverrun;
    if (now.recorder_drops > last_.recorder_drops) bits |= kHealthRecorderDrops;
    if (now.recorder_failures > last_.recorder_failures) bits |= kHealthRecordingFailed;
    if (now.inputs_refused > last_.inputs_refused) bits |= kHealthInputsRefused;
    if (now.vision_failures > last_.vision_failures) bits |= kHealthVisionFailed;
  }
  last_ = now;
  has_last_ = true;
  bits_ = bits;
  return bits;
}

void fillLoopCounters(const HealthSample& s, NavCounters* c) {
  c->ticks = s.loop.ticks;
  c->late_ticks = s.loop.late_ticks;
  c->nav_overruns = taskOverruns(s.loop, "nav");
  c->vision_overruns = taskOverruns(s.loop, "vision");
  c->recorder_drops = s.recorder_drops;
  c->inputs_refused = s.inputs_refused;
}

}  // namespace deepnav
