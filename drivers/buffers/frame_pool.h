#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "vision/types/stereo_frame.h"

namespace deepnav {

// Preallocated stereo frames shared by the camera driver (producer) and the vision worker (consumer).
// A frame is owned by exactly one side at a time: acquire() hands a free slot to the driver, which
// fills it and passes its index through an SpscRing; the worker release()s it when done. When every
// slot is busy, acquire() fails and the driver drops the new pair (counted), never an older one.
class FramePool {
 public:
  FramePool() = default;
  FramePool(const FramePool&) = delete;
  FramePool& operator=(const FramePool&) = delete;

  bool allocate(std::size_t count, int width_px, int height_px, int channels);

  // Returns a free slot index, or -1 when the pool is exhausted.
  int acquire();
  void release(int index);

  StereoFrame& frame(int index) { return frames_[static_cast<std::size_t>(index)]; }
  const StereoFrame& frame(int index) const { return frames_[static_cast<std::size_t>(index)]; }
  std::size_t size() const { return count_; }
  std::size_t exhausted() const { return exhausted_.load(std::memory_order_relaxed); }

 private:
  std::unique_ptr<StereoFrame[]> frames_;
  std::unique_ptr<std::atomic<bool>[]> busy_;
  std::size_t count_ = 0;
  std::atomic<std::size_t> exhausted_{0};
};

}  // namespace deepnav
