// Per-stream timing (scenario `timing`): stamps moved by latency, clock offset and drift exactly as
// configured, the output still time-ordered, the content the same as without timing (measured at the
// true instant); the loader's `timing` section.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_events.h"
#include "tools/sim/scenario_loader.h"

namespace deepnav::sim {
namespace {

using test::flatten;
using test::ofStream;
using test::runAll;

// Every number of the event but its stamps (the event's and the sample's).
std::vector<double> content(const SimEvent& e) {
  std::vector<double> x = flatten(e);
  return std::vector<double>(x.begin() + 3, x.end());
}

Scenario timedScenario() {
  Scenario s;
  s.duration_s = 30.0;
  s.timing.of(SimStream::kImu).clock_drift_ppm = 500.0;     // +15 ms after 30 s
  s.timing.of(SimStream::kDvl).latency_ms = 120.0;
  s.timing.of(SimStream::kCompass).latency_ms = 40.0;
  s.timing.of(SimStream::kCompass).clock_offset_ms = -250.0;  // earlier than its instant: the merger waits
  s.timing.of(SimStream::kDepth).clock_offset_ms = 75.0;
  s.timing.of(SimStream::kDepth).clock_drift_ppm = -2000.0;
  s.timing.of(SimStream::kCamera).clock_offset_ms = -12.5;    // the camera-IMU time offset
  return s;
}

TEST(SimTimingStamps, StampsShiftAsConfiguredAndContentStaysAtTheTrueInstant) {
  const Scenario timed = timedScenario();
  Scenario plain = timed;
  plain.timing = TimingConfig{};
  const std::vector<SimEvent> with = runAll(timed, 4), without = runAll(plain, 4);
  ASSERT_EQ(with.size(), without.size());
  for (int i = 0; i < kSimStreamCount; ++i) {
    const SimStream stream = static_cast<SimStream>(i);
    const std::vector<SimEvent> a = ofStream(with, stream), b = ofStream(without, stream);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    const StreamTiming& t = timed.timing.of(stream);
    for (std::size_t k = 0; k < a.size(); ++k) {
      const TimeUs instant_us = b[k].t_us;  // no faults: the stamp without timing is the instant
      const double expected_us = instant_us + (t.clock_offset_ms + t.latency_ms) * 1e3 +
                                 t.clock_drift_ppm * 1e-6 * static_cast<double>(instant_us);
      ASSERT_NEAR(static_cast<double>(a[k].t_us), expected_us, 0.5) << streamName(stream) << " " << k;
      ASSERT_EQ(std::visit([](const auto& s) { return s.t_us; }, a[k].sample), a[k].t_us);
      ASSERT_EQ(content(a[k]), content(b[k])) << streamName(stream) << " " << k;  // bit for bit
    }
  }
  for (std::size_t k = 1; k < with.size(); ++k) ASSERT_LE(with[k - 1].t_us, with[k].t_us) << k;
  // Spot values: the compass sample measured at 10 s is stamped at 9.79 s, depth at 30 s at 30.015 s.
  const std::vector<SimEvent> compass = ofStream(with, SimStream::kCompass), depth = ofStream(with, SimStream::kDepth);
  EXPECT_EQ(compass[100].t_us, 10'000'000 - 210'000);
  EXPECT_EQ(depth.back().t_us, 30'000'000 + 75'000 - 60'000);
}

TEST(SimTimingStamps, WorksWithJitterFaultsAndStaysOrdered) {
  Scenario s = timedScenario();
  FaultSpec jitter;
  jitter.stream = SimStream::kCompass;
  jitter.kind = FaultKind::kTimeJitter;
  jitter.t_start_s = 5.0;
  jitter.t_end_s = 25.0;
  jitter.std_ms = 30.0;
  s.faults.push_back(jitter);
  const std::vector<SimEvent> events = runAll(s, 9);
  for (std::size_t k = 1; k < events.size(); ++k) ASSERT_LE(events[k - 1].t_us, events[k].t_us) << k;
}

TEST(SimTimingStamps, MaxAdvanceIsTheLargestEarlierShift) {
  TimingConfig t;
  EXPECT_FALSE(t.active());
  EXPECT_EQ(t.maxAdvance_us(30'000'000), 0);
  t.of(SimStream::kDvl).latency_ms = 100.0;  // later only: nothing to wait for
  EXPECT_EQ(t.maxAdvance_us(30'000'000), 0);
  t.of(SimStream::kDepth).clock_drift_ppm = -1000.0;  // -30 ms at 30 s
  EXPECT_EQ(t.maxAdvance_us(30'000'000), 30'000);
  t.of(SimStream::kCamera).clock_offset_ms = -50.0;
  EXPECT_EQ(t.maxAdvance_us(30'000'000), 50'000);
}

TEST(SimTimingStamps, LoaderReadsTheTimingSection) {
  Scenario s;
  std::string error;
  ASSERT_TRUE(parseScenario("timing:\n  camera: {clock_offset_ms: -12.5}\n  dvl: {latency_ms: 120, clock_drift_ppm: 20}\n",
                            "t.yaml", &s, &error))
      << error;
  EXPECT_EQ(s.timing.of(SimStream::kCamera).clock_offset_ms, -12.5);
  EXPECT_EQ(s.timing.of(SimStream::kDvl).latency_ms, 120.0);
  EXPECT_EQ(s.timing.of(SimStream::kDvl).clock_drift_ppm, 20.0);
  EXPECT_FALSE(parseScenario("timing:\n  dvl: {latency_ms: -1}\n", "t.yaml", &s, &error));
  EXPECT_NE(error.find("timing.dvl.latency_ms"), std::string::npos) << error;
  EXPECT_FALSE(parseScenario("timing:\n  ground_truth: {latency_ms: 1}\n", "t.yaml", &s, &error));
  EXPECT_NE(error.find("timing"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::sim
