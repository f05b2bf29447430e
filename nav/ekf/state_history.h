#pragma once
#include <vector>

#include "nav/ekf/filter_state.h"
#include "nav/types/imu_sample.h"

namespace deepnav {

// One IMU epoch: the sample stamped t_k (it drove the step (t_{k-1}, t_k]) and the filter right after
// propagating to t_k, before the measurements stamped exactly t_k are fused.
struct HistoryEntry {
  ImuSample imu;
  FilterState state;
};

// Fixed ring of IMU epochs for delayed fusion (after PX4 EKF/RingBuffer.h: allocated once, push
// overwrites the oldest). Index 0 is the oldest entry.
class StateHistory {
 public:
  StateHistory() = default;
  StateHistory(const StateHistory&) = delete;
  StateHistory& operator=(const StateHistory&) = delete;

  bool allocate(int capacity);
  void clear() { head_ = 0; size_ = 0; }
  int size() const { return size_; }
  int capacity() const { return static_cast<int>(ring_.size()); }
  bool empty() const { return size_ == 0; }

  // Slot for a new newest entry; overwrites the oldest when full (overflowed() tells).
  HistoryEntry& push();
  void popOldest();
  HistoryEntry& at(int i) { return ring_[physical(i)]; }
  const HistoryEntry& at(int i) const { return ring_[physical(i)]; }
  TimeUs timeAt(int i) const { return at(i).imu.t_us; }

  // Index of the newest entry with time <= t_us, or -1.
  int latestAtOrBefore(TimeUs t_us) const;
  std::uint32_t overwrites() const { return overwrites_; }

 private:
  std::size_t physical(int i) const { return static_cast<std::size_t>((head_ + i) % capacity()); }

  std::vector<HistoryEntry> ring_;
  int head_ = 0;
  int size_ = 0;
  std::uint32_t overwrites_ = 0;
};

}  // namespace deepnav
