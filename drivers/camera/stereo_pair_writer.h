#pragma once
#include <cstdint>

#include "drivers/buffers/frame_pool.h"
#include "drivers/buffers/spsc_ring.h"
#include "drivers/camera/camera_status.h"
#include "drivers/camera/raw_image.h"

namespace deepnav {

// The last step of every camera driver: a matched left/right pair goes into a free slot of the
// preallocated frame pool (converted to the pool's grey or BGR layout) and the slot's index into the
// ring read by the vision worker. A full pool or ring drops the new pair and counts it.
class StereoPairWriter {
 public:
  StereoPairWriter(FramePool* pool, SpscRing<int>* frames, CameraCounters* counters)
      : pool_(pool), frames_(frames), counters_(counters) {}

  // t_us: capture time of the pair (middle of the exposure, monotonic clock); skew_us: |t_left -
  // t_right|. Returns true when the pair was handed on.
  bool write(const RawImage& left, const RawImage& right, TimeUs t_us, TimeUs skew_us,
             std::uint32_t exposure_us, std::uint64_t sequence);

 private:
  FramePool* pool_;
  SpscRing<int>* frames_;
  CameraCounters* counters_;
};

}  // namespace deepnav
