#pragma once
// The fault-injection suite's instrument: replays a dive through the bench replay with a
// ReplayFaultInjector tapped in, and compares runs tick by tick.
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "board/replay/bench_replay.h"
#include "tests/support/replay_fault_injector.h"
#include "tests/support/test_dive.h"

namespace deepnav::testing {

// printf into a std::string (g++ 12 at -O3 warns falsely on some literal + std::string chains).
inline std::string strf(const char* format, ...) __attribute__((format(printf, 1, 2)));
inline std::string strf(const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof buffer, format, args);
  va_end(args);
  return buffer;
}

struct FaultRun {
  ReplaySummary summary;
  std::unique_ptr<ReplayFaultInjector> tap;
  const std::vector<TickRecord>& ticks() const { return tap->ticks(); }
};

inline FaultRun replayWithFaults(const std::string& recording, const std::string& name,
                                 const InjectedFaultSpec& spec = {}, const std::vector<std::string>& overrides = {}) {
  FaultRun run;
  run.tap = std::make_unique<ReplayFaultInjector>(spec);
  ReplayOptions o;
  o.input_path = recording;
  o.out_dir = tempPath("fault_" + name);
  o.progress = false;
  o.overrides = overrides;
  o.tap = run.tap.get();
  std::string error;
  EXPECT_TRUE(runBenchReplay(o, &run.summary, &error)) << error;
  return run;
}

// A sensor-only dive (no rendering) of the default scenario with a `faults:` list in scenario syntax.
inline std::string sensorDive(const std::string& name, const std::string& faults_yaml, double duration_s = 30.0,
                              std::uint64_t seed = 5) {
  return makeTestDive(name, duration_s, seed, false, {{"faults: []", strf("faults: %s", faults_yaml.c_str())}});
}

inline int nonFiniteTicks(const FaultRun& r) {
  return static_cast<int>(std::count_if(r.ticks().begin(), r.ticks().end(), [](const TickRecord& t) { return !t.finite; }));
}

// Largest position and orientation difference between two runs of the same dive, over the ticks at the
// same time where both are aligned, from t_from_s on.
struct Deviation {
  double position_m = 0.0;
  double angle_rad = 0.0;
};

inline Deviation maxDeviation(const FaultRun& a, const FaultRun& b, double t_from_s = 0.0, double t_to_s = 1e9) {
  Deviation d;
  std::size_t j = 0;
  for (const TickRecord& x : a.ticks()) {
    while (j < b.ticks().size() && b.ticks()[j].t_us < x.t_us) ++j;
    if (j >= b.ticks().size()) break;
    const TickRecord& y = b.ticks()[j];
    if (y.t_us != x.t_us || !x.aligned || !y.aligned || usToS(x.t_us) < t_from_s || usToS(x.t_us) > t_to_s) continue;
    d.position_m = std::max(d.position_m, (x.p_robot_in_odom_m - y.p_robot_in_odom_m).norm());
    d.angle_rad = std::max(d.angle_rad, x.q_odom_robot.angularDistance(y.q_odom_robot));
  }
  return d;
}

// The tick record at (or right after) t_s.
inline const TickRecord& tickAt(const FaultRun& r, double t_s) {
  const auto it = std::lower_bound(r.ticks().begin(), r.ticks().end(), sToUs(t_s),
                                   [](const TickRecord& t, TimeUs v) { return t.t_us < v; });
  return it == r.ticks().end() ? r.ticks().back() : *it;
}

// First tick time (s) at or after t_from_s whose fault bits contain `bits` (any of them); -1: never.
inline double firstFlagged(const FaultRun& r, std::uint32_t bits, double t_from_s, double t_to_s = 1e9) {
  for (const TickRecord& t : r.ticks()) {
    const double s = usToS(t.t_us);
    if (s >= t_from_s && s <= t_to_s && (t.faults & bits)) return s;
  }
  return -1.0;
}

// First tick time (s) at or after t_from_s whose fault bits contain none of `bits`; -1: never.
inline double firstClear(const FaultRun& r, std::uint32_t bits, double t_from_s) {
  for (const TickRecord& t : r.ticks()) {
    if (usToS(t.t_us) >= t_from_s && !(t.faults & bits)) return usToS(t.t_us);
  }
  return -1.0;
}

// Samples of one kind that differ from the clean run's sample with the same stamp (the faulty ones),
// and how many of them the filter accepted.
struct FaultySamples {
  int faulty = 0;
  int accepted = 0;
};

inline FaultySamples faultySamples(const FaultRun& clean, const FaultRun& faulted, InputKind kind) {
  FaultySamples f;
  std::size_t j = 0;
  const auto& a = clean.tap->inputs();
  for (const InputRecord& x : faulted.tap->inputs()) {
    if (x.kind != kind) continue;
    while (j < a.size() && (a[j].t_us < x.t_us || (a[j].t_us == x.t_us && a[j].kind != kind))) ++j;
    if (j >= a.size() || a[j].t_us != x.t_us) continue;
    if (a[j].value == x.value) continue;
    ++f.faulty;
    f.accepted += x.accepted;
  }
  return f;
}

}  // namespace deepnav::testing
