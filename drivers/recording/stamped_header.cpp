#include "drivers/recording/stamped_header.h"

#include <cstdint>
#include <string>

namespace deepnav {

void writeStampedHeader(cdr::CdrWriter& w, TimeUs t_us, Topic topic) {
  TimeUs sec = t_us / kUsPerS, rem = t_us % kUsPerS;
  if (rem < 0) {
    rem += kUsPerS;
    --sec;
  }
  w.i32(static_cast<std::int32_t>(sec));
  w.u32(static_cast<std::uint32_t>(rem * 1000));
  w.string(topicInfo(topic).frame_id);
}

bool readStampedHeader(cdr::CdrReader& r, TimeUs* t_us) {
  std::int32_t sec = 0;
  std::uint32_t nanosec = 0;
  std::string frame_id;  // short frame names fit the small-string buffer: no allocation
  if (!r.i32(&sec) || !r.u32(&nanosec) || !r.string(&frame_id) || nanosec >= 1000000000u) return false;
  *t_us = static_cast<TimeUs>(sec) * kUsPerS + static_cast<TimeUs>(nanosec / 1000);
  return true;
}

}  // namespace deepnav
