#include "board/loop/scheduler.h"

#include <cstdio>
#include <cstring>

namespace deepnav {
namespace {

void updateMax(std::atomic<std::int64_t>& m, std::int64_t v) {
  std::int64_t cur = m.load(std::memory_order_relaxed);
  while (v > cur && !m.compare_exchange_weak(cur, v, std::memory_order_relaxed)) {
  }
}

}  // namespace

bool Scheduler::init(const TaskSpec* table, int count, double late_tolerance, std::string* error) {
  auto fail = [&](const std::string& msg) {
    if (error) *error = "scheduler: " + msg;
    return false;
  };
  if (count <= 0 || count > kMaxTasks) return fail("the table needs 1 to 8 tasks");
  tick_rate_hz_ = 0;
  for (int i = 0; i < count; ++i) {
    const TaskSpec& t = table[i];
    if (t.rate_hz <= 0 || t.budget_us <= 0) return fail(std::string("task '") + t.name + "' needs rate and budget > 0");
    if (!t.own_thread && t.rate_hz > tick_rate_hz_) tick_rate_hz_ = t.rate_hz;
  }
  if (tick_rate_hz_ == 0) return fail("no task runs in the loop thread");
  for (int i = 0; i < count; ++i) {
    const TaskSpec& t = table[i];
    if (!t.own_thread && tick_rate_hz_ % t.rate_hz != 0) {
      return fail(std::string("task '") + t.name + "' rate " + std::to_string(t.rate_hz) +
                  " Hz does not divide the tick rate " + std::to_string(tick_rate_hz_) + " Hz");
    }
    table_[static_cast<std::size_t>(i)] = t;
    divider_[static_cast<std::size_t>(i)] = t.own_thread ? 0 : static_cast<std::uint64_t>(tick_rate_hz_ / t.rate_hz);
  }
  count_ = count;
  period_us_ = kUsPerS / tick_rate_hz_;
  late_threshold_us_ = static_cast<TimeUs>(late_tolerance * static_cast<double>(period_us_));
  return true;
}

int Scheduler::findTask(const char* name) const {
  for (int i = 0; i < count_; ++i) {
    if (std::strcmp(table_[static_cast<std::size_t>(i)].name, name) == 0) return i;
  }
  return -1;
}

bool Scheduler::due(int task, std::uint64_t tick_index) const {
  const std::uint64_t d = divider_[static_cast<std::size_t>(task)];
  return d != 0 && tick_index % d == 0;
}

void Scheduler::recordTickStart(TimeUs scheduled_us, TimeUs actual_us) {
  ticks_.fetch_add(1, std::memory_order_relaxed);
  const TimeUs lateness = actual_us - scheduled_us;
  updateMax(max_lateness_us_, lateness);
  if (lateness > late_threshold_us_) late_ticks_.fetch_add(1, std::memory_order_relaxed);
}

void Scheduler::recordRun(int task, std::int64_t elapsed_us) {
  if (task < 0 || task >= count_) return;
  TaskStats& s = stats_[static_cast<std::size_t>(task)];
  s.runs.fetch_add(1, std::memory_order_relaxed);
  s.total_us.fetch_add(elapsed_us, std::memory_order_relaxed);
  updateMax(s.max_us, elapsed_us);
  if (elapsed_us > table_[static_cast<std::size_t>(task)].budget_us) s.overruns.fetch_add(1, std::memory_order_relaxed);
}

LoopStats Scheduler::stats() const {
  LoopStats out;
  out.task_count = count_;
  for (int i = 0; i < count_; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out.names[k] = table_[k].name;
    out.runs[k] = stats_[k].runs.load(std::memory_order_relaxed);
    out.overruns[k] = stats_[k].overruns.load(std::memory_order_relaxed);
    out.max_us[k] = stats_[k].max_us.load(std::memory_order_relaxed);
    out.mean_us[k] = out.runs[k] ? static_cast<double>(stats_[k].total_us.load(std::memory_order_relaxed)) /
                                       static_cast<double>(out.runs[k])
                                 : 0.0;
  }
  out.ticks = ticks_.load(std::memory_order_relaxed);
  out.late_ticks = late_ticks_.load(std::memory_order_relaxed);
  out.max_lateness_us = max_lateness_us_.load(std::memory_order_relaxed);
  return out;
}

std::string formatLoopStats(const LoopStats& s) {
  std::string out = "task          runs   overruns   mean_us   max_us\n";
  char line[160];
  for (int i = 0; i < s.task_count; ++i) {
    const auto k = static_cast<std::size_t>(i);
    std::snprintf(line, sizeof line, "%-10s %7llu %10llu %9.1f %8lld\n", s.names[k],
                  static_cast<unsigned long long>(s.runs[k]), static_cast<unsigned long long>(s.overruns[k]),
                  s.mean_us[k], static_cast<long long>(s.max_us[k]));
    out += line;
  }
  std::snprintf(line, sizeof line, "ticks %llu, late ticks %llu, max lateness %lld us\n",
                static_cast<unsigned long long>(s.ticks), static_cast<unsigned long long>(s.late_ticks),
                static_cast<long long>(s.max_lateness_us));
  out += line;
  return out;
}

}  // namespace deepnav
