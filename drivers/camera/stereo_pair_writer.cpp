#include "drivers/camera/stereo_pair_writer.h"

namespace deepnav {

bool StereoPairWriter::write(const RawImage& left, const RawImage& right, TimeUs t_us, TimeUs skew_us,
                             std::uint32_t exposure_us, std::uint64_t sequence) {
  const int slot = pool_->acquire();
  if (slot < 0) {
    counters_->pool_exhausted.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  StereoFrame& f = pool_->frame(slot);
  if (!convertRawImage(left, f.left) || !convertRawImage(right, f.right)) {
    // The drivers check size and format before pairing; reaching here means a driver bug.
    pool_->release(slot);
    counters_->left.count(CameraFrameStatus::kWrongFormat);
    return false;
  }
  f.t_us = t_us;
  f.exposure_us = exposure_us;
  f.sequence = sequence;
  f.rectified = false;
  if (!frames_->push(slot)) {
    pool_->release(slot);
    counters_->ring_full.fetch_add(1, std::memory_order_relaxed);
    return false;
  }
  counters_->pairs.fetch_add(1, std::memory_order_relaxed);
  if (skew_us > counters_->max_pair_skew_us.load(std::memory_order_relaxed)) {
    counters_->max_pair_skew_us.store(skew_us, std::memory_order_relaxed);
  }
  return true;
}

}  // namespace deepnav
