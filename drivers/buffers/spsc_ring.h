#pragma once
#include <atomic>
#include <cstddef>
#include <memory>
#include <new>

namespace deepnav {

// Single-producer / single-consumer ring between a driver thread and the nav loop.
// Storage is allocated once by allocate() (at start-up, from the config) and never again.
// Lock-free: the producer owns head_, the consumer owns tail_. When full, push() refuses the new
// sample and counts it, so the consumer never sees a half-written slot; samples already queued are kept.
template <typename T>
class SpscRing {
 public:
  using value_type = T;

  SpscRing() = default;
  SpscRing(const SpscRing&) = delete;
  SpscRing& operator=(const SpscRing&) = delete;

  // Capacity is rounded up to a power of two. Returns false when the allocation fails or size is 0.
  bool allocate(std::size_t capacity) {
    if (capacity == 0) return false;
    std::size_t n = 1;
    while (n < capacity) n <<= 1;
    slots_.reset(new (std::nothrow) T[n]);
    if (!slots_) return false;
    mask_ = n - 1;
    head_.store(0, std::memory_order_relaxed);
    tail_.store(0, std::memory_order_relaxed);
    dropped_.store(0, std::memory_order_relaxed);
    return true;
  }

  std::size_t capacity() const { return slots_ ? mask_ + 1 : 0; }

  // Producer side. Returns false (and counts a drop) when the ring is full or not allocated.
  bool push(const T& value) {
    const std::size_t head = head_.load(std::memory_order_relaxed);
    const std::size_t tail = tail_.load(std::memory_order_acquire);
    if (!slots_ || head - tail > mask_) {
      dropped_.fetch_add(1, std::memory_order_relaxed);
      return false;
    }
    slots_[head & mask_] = value;
    head_.store(head + 1, std::memory_order_release);
    return true;
  }

  // Consumer side: oldest sample, or nullptr when empty. Valid until pop().
  const T* front() const {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail == head_.load(std::memory_order_acquire)) return nullptr;
    return &slots_[tail & mask_];
  }

  void pop() {
    const std::size_t tail = tail_.load(std::memory_order_relaxed);
    if (tail != head_.load(std::memory_order_acquire)) tail_.store(tail + 1, std::memory_order_release);
  }

  bool tryPop(T& out) {
    const T* f = front();
    if (!f) return false;
    out = *f;
    pop();
    return true;
  }

  std::size_t size() const {
    return head_.load(std::memory_order_acquire) - tail_.load(std::memory_order_acquire);
  }
  std::size_t dropped() const { return dropped_.load(std::memory_order_relaxed); }

 private:
  std::unique_ptr<T[]> slots_;
  std::size_t mask_ = 0;
  alignas(64) std::atomic<std::size_t> head_{0};
  alignas(64) std::atomic<std::size_t> tail_{0};
  alignas(64) std::atomic<std::size_t> dropped_{0};
};

}  // namespace deepnav
