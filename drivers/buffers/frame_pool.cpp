#include "drivers/buffers/frame_pool.h"

#include <new>

namespace deepnav {

bool FramePool::allocate(std::size_t count, int width_px, int height_px, int channels) {
  if (count == 0) return false;
  frames_.reset(new (std::nothrow) StereoFrame[count]);
  busy_.reset(new (std::nothrow) std::atomic<bool>[count]);
  if (!frames_ || !busy_) return false;
  for (std::size_t i = 0; i < count; ++i) {
    if (!allocateStereoFrame(frames_[i], width_px, height_px, channels)) return false;
    busy_[i].store(false, std::memory_order_relaxed);
  }
  count_ = count;
  return true;
}

int FramePool::acquire() {
  for (std::size_t i = 0; i < count_; ++i) {
    bool expected = false;
    if (busy_[i].compare_exchange_strong(expected, true, std::memory_order_acq_rel)) {
      return static_cast<int>(i);
    }
  }
  exhausted_.fetch_add(1, std::memory_order_relaxed);
  return -1;
}

void FramePool::release(int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= count_) return;
  busy_[static_cast<std::size_t>(index)].store(false, std::memory_order_release);
}

}  // namespace deepnav
