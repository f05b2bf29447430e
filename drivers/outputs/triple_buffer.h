#pragma once
#include <array>
#include <atomic>
#include <cstdint>

namespace deepnav {

// Latest-value hand-over between one writer and one reader that never blocks either side: the writer
// fills its back slot and swaps it with the middle slot; the reader swaps the middle slot with its front
// slot when the writer left something new there. Every slot is touched by one thread at a time, so a
// value is never read while written (unlike a seqlock), and nothing is allocated after construction.
template <typename T>
class TripleBuffer {
 public:
  // Writer side.
  T& back() { return slots_[back_]; }
  void publish() {
    const std::uint8_t old = middle_.exchange(static_cast<std::uint8_t>(back_ | kFresh), std::memory_order_acq_rel);
    back_ = old & kIndex;
  }

  // Reader side: true (and front() updated) when a value newer than the last one read is there.
  bool update() {
    if ((middle_.load(std::memory_order_relaxed) & kFresh) == 0) return false;
    const std::uint8_t old = middle_.exchange(front_, std::memory_order_acq_rel);
    front_ = old & kIndex;
    return true;
  }
  const T& front() const { return slots_[front_]; }

 private:
  static constexpr std::uint8_t kFresh = 0x4;
  static constexpr std::uint8_t kIndex = 0x3;
  std::array<T, 3> slots_{};
  std::uint8_t back_ = 0;                // writer's
  std::atomic<std::uint8_t> middle_{1};  // shared: index | kFresh
  std::uint8_t front_ = 2;               // reader's
};

}  // namespace deepnav
