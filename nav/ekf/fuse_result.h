#pragma once
#include <cstdint>

namespace deepnav {

// What became of one measurement handed to the filter.
enum class FuseStatus : std::uint8_t {
  kAccepted = 0,     // fused at its capture time
  kRejected,         // innovation gate failed (or unusable geometry)
  kQueued,           // newer than the last IMU sample: fused when the IMU catches up
  kDroppedLate,      // older than the delay window (or than the retained history)
  kBadInput,         // NaN, Inf, negative variance, invalid flag: refused at the door
  kNotAligned,       // the filter has not been aligned or reset yet
  kRefused,          // refused by a health check of its source (magnetic disturbance, mag_disturbance.h):
                     // not a gate failure, so it neither counts as rejected nor leads to a gate reset
};

struct FuseResult {
  FuseStatus status = FuseStatus::kNotAligned;
  double test_ratio = 0.0;  // innovation test ratio (<= 1 passes); 0 when not gated
};

}  // namespace deepnav
