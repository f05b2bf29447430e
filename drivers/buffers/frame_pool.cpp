#include "drivers/buffers/frame_pool.h"

#include <new>

namespace deepnav {

bool FramePool::allocate(std::size_t count, int width_px, int height_px, int channels) {
  if (count == 0) return false;
  frames_.reset(new (std::nothrow) StereoFrame[count]);
  refs_.reset(new (std::nothrow) std::atomic<int>[count]);
  if (!frames_ || !refs_) return false;
  for (std::size_t i = 0; i < count; ++i) {
    if (!allocateStereoFrame(frames_[i], width_px, height_px, channels)) return false;
    refs_[i].store(0, std::memory_order_relaxed);
  }
  count_ = count;
  return true;
}

int FramePool::acquire() {
  for (std::size_t i = 0; i < count_; ++i) {
    int expected = 0;
    if (refs_[i].compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) {
      return static_cast<int>(i);
    }
  }
  exhausted_.fetch_add(1, std::memory_order_relaxed);
  return -1;
}

void FramePool::addRef(int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= count_) return;
  refs_[static_cast<std::size_t>(index)].fetch_add(1, std::memory_order_acq_rel);
}

void FramePool::release(int index) {
  if (index < 0 || static_cast<std::size_t>(index) >= count_) return;
  refs_[static_cast<std::size_t>(index)].fetch_sub(1, std::memory_order_acq_rel);
}

}  // namespace deepnav
