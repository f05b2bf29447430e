#pragma once
#include <array>
#include <atomic>
#include <cstdint>
#include <string>

#include "nav/types/loop_stats.h"
#include "nav/types/time.h"

namespace deepnav {

// One row of the scheduler table (ArduSub style): a task, its rate and its time budget.
struct TaskSpec {
  const char* name;
  int rate_hz;
  int budget_us;
  bool own_thread;  // runs in a worker thread (vision); the loop only counts its runs and overruns
};

// Counters of one task. Written by the one thread that runs the task, read by anyone (relaxed atomics).
struct TaskStats {
  std::atomic<std::uint64_t> runs{0};
  std::atomic<std::uint64_t> overruns{0};
  std::atomic<std::int64_t> max_us{0};
  std::atomic<std::int64_t> total_us{0};
};

// Fixed-rate scheduler: the base tick runs at the fastest rate in the table; every other loop task
// runs every (tick_rate / rate) ticks. Rates must divide the tick rate so that a task's period is exact.
class Scheduler {
 public:
  static constexpr int kMaxTasks = LoopStats::kMaxTasks;

  // Validates the table; on error names the task and the reason.
  bool init(const TaskSpec* table, int count, double late_tolerance, std::string* error);

  int tickRateHz() const { return tick_rate_hz_; }
  TimeUs periodUs() const { return period_us_; }
  const TaskSpec& task(int i) const { return table_[static_cast<std::size_t>(i)]; }
  int findTask(const char* name) const;

  // Is task i due at this tick index? (Tasks in their own thread are never due here.)
  bool due(int task, std::uint64_t tick_index) const;

  // The loop reports each tick's start: scheduled vs actual time, for late-tick counting.
  void recordTickStart(TimeUs scheduled_us, TimeUs actual_us);
  // Whoever ran task i reports its execution time; longer than the budget counts as an overrun.
  void recordRun(int task, std::int64_t elapsed_us);

  LoopStats stats() const;

 private:
  std::array<TaskSpec, kMaxTasks> table_{};
  std::array<std::uint64_t, kMaxTasks> divider_{};
  std::array<TaskStats, kMaxTasks> stats_{};
  int count_ = 0;
  int tick_rate_hz_ = 0;
  TimeUs period_us_ = 0;
  TimeUs late_threshold_us_ = 0;
  std::atomic<std::uint64_t> ticks_{0};
  std::atomic<std::uint64_t> late_ticks_{0};
  std::atomic<std::int64_t> max_lateness_us_{0};
};

// Human-readable table of the loop statistics (for `deepnav replay` and logs).
std::string formatLoopStats(const LoopStats& stats);

}  // namespace deepnav
