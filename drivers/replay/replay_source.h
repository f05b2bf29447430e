#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <thread>

#include "drivers/buffers/live_inputs.h"
#include "drivers/clock/loop_clock.h"
#include "drivers/replay/recording_reader.h"

namespace deepnav {

// A recording played as if it were the vehicle's sensors: a driver thread that pushes each sample into
// the live input rings (and each stereo pair into the frame pool) when the wall clock reaches its
// recorded time. The loop that consumes them cannot tell it from a dive.
class ReplaySource {
 public:
  ReplaySource() = default;
  ~ReplaySource() { stop(); }
  ReplaySource(const ReplaySource&) = delete;
  ReplaySource& operator=(const ReplaySource&) = delete;

  bool open(const std::string& path, std::string* error);
  // First sample time of the recording (valid after open()).
  TimeUs firstTimeUs() const { return first_us_; }
  TimeUs lastTimeUs() const { return last_us_; }

  // Plays from now on: sample time t is pushed at monotonic time t + clock_offset... i.e. at
  // wall = t - clock_offset_us (the loop uses the same offset to read the recording's clock).
  void start(LiveInputs* inputs, TimeUs clock_offset_us) { start(inputs, LoopClock{clock_offset_us}); }
  // The same on any mapping of the monotonic clock (the loop's own, e.g. faster than real time).
  void start(LiveInputs* inputs, const LoopClock& clock);
  void stop();
  bool finished() const { return finished_.load(std::memory_order_acquire); }

  std::uint64_t pushed() const { return pushed_.load(std::memory_order_relaxed); }
  std::uint64_t refused() const { return refused_.load(std::memory_order_relaxed); }  // full ring or pool
  const std::string& error() const { return error_; }

 private:
  void run();
  bool push(const ReplayEvent& e);

  std::string path_;
  RecordingReader reader_;
  LiveInputs* inputs_ = nullptr;
  LoopClock clock_;
  TimeUs first_us_ = 0;
  TimeUs last_us_ = 0;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> finished_{false};
  std::atomic<std::uint64_t> pushed_{0};
  std::atomic<std::uint64_t> refused_{0};
  std::string error_;
};

}  // namespace deepnav
