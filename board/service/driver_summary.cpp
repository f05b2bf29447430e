#include "board/service/driver_summary.h"

#include <cstdio>

namespace deepnav {
namespace {

std::string serialPart(const char* name, const SensorStreamDecoder::Counters& c, uint64_t reopens) {
  char line[200];
  std::snprintf(line, sizeof line, "%s %llu frames, %llu bad, %llu refused, %llu reopens", name,
                static_cast<unsigned long long>(c.frames), static_cast<unsigned long long>(c.bad_frames),
                static_cast<unsigned long long>(c.sink_refused), static_cast<unsigned long long>(reopens));
  return line;
}

std::string canPart(const SensorThreads::Status& s) {
  char line[240];
  std::snprintf(line, sizeof line, "can %llu frames, %llu bad, %llu refused, %llu reopens, bus %s, tx errors %d, rx errors %d",
                static_cast<unsigned long long>(s.can.frames), static_cast<unsigned long long>(s.can.bad_frames),
                static_cast<unsigned long long>(s.can.sink_refused), static_cast<unsigned long long>(s.can.reopens),
                s.can_bus_state[0] != '\0' ? s.can_bus_state : "unknown", s.can_tx_errors, s.can_rx_errors);
  return line;
}

std::string depthPart(const SensorThreads::Status& s) {
  char line[120];
  std::snprintf(line, sizeof line, "depth %llu reads, %llu failed", static_cast<unsigned long long>(s.depth_reads),
                static_cast<unsigned long long>(s.depth_failures));
  return line;
}

void append(std::string* out, const std::string& part) {
  if (!out->empty()) *out += " | ";
  *out += part;
}

}  // namespace

std::string formatDriverSummary(const SensorThreads::Status& s) {
  std::string out;
  if (s.dvl_on) append(&out, serialPart("dvl", s.dvl, s.dvl_reopens));
  if (s.ahrs_on) append(&out, serialPart("ahrs", s.ahrs, s.ahrs_reopens));
  if (s.can_on) append(&out, canPart(s));
  if (s.depth_on) append(&out, depthPart(s));
  return out;
}

}  // namespace deepnav
