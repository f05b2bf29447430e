#pragma once
#include <array>
#include <cstdint>

namespace deepnav {

// A plain copy of the statistics for reports and outputs.
struct LoopStats {
  static constexpr int kMaxTasks = 8;
  int task_count = 0;
  std::array<const char*, kMaxTasks> names{};
  std::array<std::uint64_t, kMaxTasks> runs{};
  std::array<std::uint64_t, kMaxTasks> overruns{};
  std::array<std::int64_t, kMaxTasks> max_us{};
  std::array<double, kMaxTasks> mean_us{};
  std::uint64_t ticks = 0;
  std::uint64_t late_ticks = 0;
  std::int64_t max_lateness_us = 0;
};

}  // namespace deepnav
