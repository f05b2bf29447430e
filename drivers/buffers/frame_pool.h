#pragma once
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

#include "vision/types/stereo_frame.h"

namespace deepnav {

// Preallocated stereo frames shared by the camera driver (producer) and the vision worker (consumer).
// acquire() hands a free slot (one reference) to the driver, which fills it and passes its index
// through SpscRings; each extra consumer (vision worker, recorder) takes a reference with addRef() and
// release()s it when done. The slot is free again when its count drops to zero. When every slot is
// busy, acquire() fails and the driver drops the new pair (counted), never an older one.
class FramePool {
 public:
  FramePool() = default;
  FramePool(const FramePool&) = delete;
  FramePool& operator=(const FramePool&) = delete;

  bool allocate(std::size_t count, int width_px, int height_px, int channels);

  // Returns a free slot index, or -1 when the pool is exhausted.
  int acquire();
  void addRef(int index);
  void release(int index);

  StereoFrame& frame(int index) { return frames_[static_cast<std::size_t>(index)]; }
  const StereoFrame& frame(int index) const { return frames_[static_cast<std::size_t>(index)]; }
  std::size_t size() const { return count_; }
  std::size_t exhausted() const { return exhausted_.load(std::memory_order_relaxed); }

 private:
  std::unique_ptr<StereoFrame[]> frames_;
  std::unique_ptr<std::atomic<int>[]> refs_;
  std::size_t count_ = 0;
  std::atomic<std::size_t> exhausted_{0};
};

}  // namespace deepnav
