#include "board/service/status_text.h"

#include <cstdio>

namespace deepnav {
namespace {

const char* sensorState(std::uint32_t faults, NavSource s) {
  if (faults & staleBit(s)) return "stale";
  if (faults & rejectBit(s)) return "rejected";
  return "ok";
}

}  // namespace

const char* stageName(NavStage stage) {
  switch (stage) {
    case NavStage::kInit: return "0 init";
    case NavStage::kWorkspace: return "1 workspace";
    case NavStage::kOptimised: return "2 optimised";
  }
  return "?";
}

std::string healthWords(std::uint32_t h) {
  static constexpr struct {
    std::uint32_t bit;
    const char* word;
  } kWords[] = {{kHealthLoopStalled, "stalled"},          {kHealthLoopLate, "late"},
                {kHealthNavOverrun, "nav-overrun"},        {kHealthVisionOverrun, "vision-overrun"},
                {kHealthRecorderDrops, "recorder-drops"},  {kHealthRecordingFailed, "recording-failed"},
                {kHealthInputsRefused, "inputs-refused"},  {kHealthSensorStale, "sensor-stale"},
                {kHealthSensorRejected, "sensor-rejected"}, {kHealthNotFinite, "not-finite"},
                {kHealthVisionFailed, "vision-failed"}};
  std::string s;
  for (const auto& w : kWords) {
    if ((h & w.bit) == 0) continue;
    if (!s.empty()) s += ' ';
    s += w.word;
  }
  return s.empty() ? "ok" : s;
}

std::string formatStatus(const NavOutput& out) {
  const NavSolution& s = out.solution;
  const NavCounters& c = out.counters;
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "stage %s | health %s | ticks %llu, late %llu, overruns %llu/%llu | imu %s (%llu), dvl %s (%llu), "
                "depth %s (%llu), heading %s (%llu), attitude %s (%llu), markers %s, camera %s (%llu)",
                stageName(s.stage), healthWords(out.health).c_str(), static_cast<unsigned long long>(c.ticks),
                static_cast<unsigned long long>(c.late_ticks), static_cast<unsigned long long>(c.nav_overruns),
                static_cast<unsigned long long>(c.vision_overruns), sensorState(s.faults, kSrcImu),
                static_cast<unsigned long long>(c.imu), sensorState(s.faults, kSrcDvl),
                static_cast<unsigned long long>(c.dvl), sensorState(s.faults, kSrcDepth),
                static_cast<unsigned long long>(c.depth), sensorState(s.faults, kSrcHeading),
                static_cast<unsigned long long>(c.heading), sensorState(s.faults, kSrcAttitude),
                static_cast<unsigned long long>(c.attitude), sensorState(s.faults, kSrcMarkers),
                sensorState(s.faults, kSrcCamera), static_cast<unsigned long long>(c.vision));
  return buf;
}

}  // namespace deepnav
