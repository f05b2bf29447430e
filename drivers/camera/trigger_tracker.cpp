#include "drivers/camera/trigger_tracker.h"

namespace deepnav {

bool TriggerTracker::beginTrigger(std::int64_t tick, TimeUs now_us) {
  if (outstanding_ >= 0) {
    ++counts_.skipped;
    if (now_us - outstanding_since_us_ >= timeout_us_) {
      ++counts_.timeouts;
      abandon(now_us);
    }
    return false;
  }
  if (late_frame_possible_) {
    if (now_us < quiet_until_us_) {
      ++counts_.skipped;
      return false;
    }
    late_frame_possible_ = false;
  }
  outstanding_ = tick;
  outstanding_since_us_ = now_us;
  return true;
}

std::int64_t TriggerTracker::onFrame(TimeUs arrival_us, TimeUs* written_us) {
  if (outstanding_ >= 0 && arrival_us >= outstanding_since_us_) {
    const std::int64_t tick = outstanding_;
    if (written_us != nullptr) *written_us = outstanding_since_us_;
    outstanding_ = -1;
    return tick;
  }
  // Nothing outstanding: the late frame of an abandoned trigger (the only one that can come, so the
  // camera may be triggered again at once), or a stray one. Arrived before the outstanding trigger
  // was written: not its answer (that trigger stays outstanding).
  ++counts_.unattributed;
  if (outstanding_ < 0) late_frame_possible_ = false;
  return -1;
}

}  // namespace deepnav
