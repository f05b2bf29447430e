#pragma once
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>

#include "nav/types/time.h"

namespace deepnav {

// Why a frame from one camera was or was not passed on. The first block mirrors Aravis's buffer
// statuses (ArvBufferStatus); the rest are the driver's own checks. Only kOk frames reach the pairing.
enum class CameraFrameStatus : int {
  kOk = 0,
  kCleared,             // buffer emptied before use
  kTimeout,             // frame not completed in time
  kMissingPackets,      // GigE Vision packets lost and not resent
  kWrongPacketId,       // stream protocol error
  kSizeMismatch,        // image larger than the buffer
  kFilling,             // still being filled (never complete)
  kAborted,             // acquisition stopped while filling
  kPayloadNotSupported, // not an image payload (the driver's check)
  kUnknown,             // a status this driver does not know
  kWrongFormat,         // complete, but not the configured width, height or pixel format
  kDeviceError,         // V4L2: the driver flagged the buffer (V4L2_BUF_FLAG_ERROR)
  kCount
};
constexpr std::size_t kFrameStatusCount = static_cast<std::size_t>(CameraFrameStatus::kCount);

const char* frameStatusName(CameraFrameStatus status);

// A snapshot of one camera's counters.
struct CameraSideStatus {
  std::array<std::uint64_t, kFrameStatusCount> frames{};  // per CameraFrameStatus
  bool connected = false;
  bool stale = false;            // no good frame for camera.stale_after_s
  std::uint64_t stale_events = 0;
  std::uint64_t reconnects = 0;  // successful reopenings after a loss
  std::uint64_t reconnect_failures = 0;
  std::uint64_t control_lost = 0;  // GigE Vision control failures (heartbeat, failed trigger write)
  std::uint64_t triggers = 0;      // software triggers sent
  std::uint64_t trigger_skips = 0;     // ticks not triggered: the previous trigger unanswered, or resynchronising
  std::uint64_t trigger_timeouts = 0;  // software triggers never answered
  std::uint64_t unattributed = 0;      // frames answering no known software trigger (dropped)
  std::uint64_t slow_triggers = 0;     // frames whose trigger write left the exposure start unknown (dropped)
  TimeUs last_good_frame_us = 0;  // monotonic time of the last kOk frame (0: none yet)

  std::uint64_t bad() const;  // frames with any status but kOk
};

struct CameraStatus {
  CameraSideStatus left, right;
  std::uint64_t pairs = 0;           // pairs handed to the frame ring
  std::uint64_t unpaired = 0;        // good frames dropped for want of a partner within tolerance
  std::uint64_t pool_exhausted = 0;  // pairs dropped: no free frame in the pool
  std::uint64_t ring_full = 0;       // pairs dropped: the frame ring to the vision worker was full
  TimeUs max_pair_skew_us = 0;       // largest |t_left - t_right| of a delivered pair
};

// One JSON object (no newline) with every counter, for logs and `deepnav camera`.
std::string cameraStatusJson(const CameraStatus& status);

// The live counters: written by the driver thread, read by anyone through snapshot().
class CameraCounters {
 public:
  struct Side {
    std::array<std::atomic<std::uint64_t>, kFrameStatusCount> frames{};
    std::atomic<bool> connected{false};
    std::atomic<bool> stale{false};
    std::atomic<std::uint64_t> stale_events{0};
    std::atomic<std::uint64_t> reconnects{0};
    std::atomic<std::uint64_t> reconnect_failures{0};
    std::atomic<std::uint64_t> control_lost{0};
    std::atomic<std::uint64_t> triggers{0};
    std::atomic<std::uint64_t> trigger_skips{0};
    std::atomic<std::uint64_t> trigger_timeouts{0};
    std::atomic<std::uint64_t> unattributed{0};
    std::atomic<std::uint64_t> slow_triggers{0};
    std::atomic<TimeUs> last_good_frame_us{0};

    void count(CameraFrameStatus s) {
      frames[static_cast<std::size_t>(s)].fetch_add(1, std::memory_order_relaxed);
    }
  };
  Side left, right;
  std::atomic<std::uint64_t> pairs{0};
  std::atomic<std::uint64_t> unpaired{0};
  std::atomic<std::uint64_t> pool_exhausted{0};
  std::atomic<std::uint64_t> ring_full{0};
  std::atomic<TimeUs> max_pair_skew_us{0};

  Side& side(int index) { return index == 0 ? left : right; }
  CameraStatus snapshot() const;
};

}  // namespace deepnav
