// The fault kinds added for the fault-injection suite: garbage, slow, intermittent, clock_jump.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_events.h"
#include "tools/sim/faults/fault_schedule.h"
#include "tools/sim/faults/garbage_values.h"

namespace deepnav::sim {
namespace {

using test::ofStream;
using test::fault;
using test::runAll;
using test::withFault;

constexpr std::uint64_t kSeed = 33;

std::vector<SimEvent> cleanStream(SimStream stream) {
  return ofStream(runAll(withFault(fault(SimStream::kImu, FaultKind::kDropout, 99, 100)), kSeed), stream);
}

bool inWindow(TimeUs t_us, double start_s, double end_s) { return t_us >= sToUs(start_s) && t_us < sToUs(end_s); }

TEST(SimFaultKinds, NamesRoundTrip) {
  for (int k = 0; k < 8; ++k) {
    const auto kind = static_cast<FaultKind>(k);
    EXPECT_EQ(faultKindFromName(faultKindName(kind)), kind);
  }
  EXPECT_FALSE(faultKindFromName("bogus").has_value());
}

TEST(SimFaultKinds, GarbageReplacesTheContentInsideTheWindowOnly) {
  // GIVEN compass garbage between 5 and 8 s
  const std::vector<SimEvent> a = cleanStream(SimStream::kCompass);
  const std::vector<SimEvent> b =
      ofStream(runAll(withFault(fault(SimStream::kCompass, FaultKind::kGarbage, 5.0, 8.0)), kSeed), SimStream::kCompass);
  ASSERT_EQ(a.size(), b.size());
  int far = 0, inside = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double ha = std::get<HeadingSample>(a[i].sample).heading_rad;
    const double hb = std::get<HeadingSample>(b[i].sample).heading_rad;
    EXPECT_EQ(a[i].t_us, b[i].t_us);
    EXPECT_GE(hb, 0.0);
    EXPECT_LT(hb, 2.0 * M_PI);
    if (!inWindow(a[i].t_us, 5.0, 8.0)) {
      EXPECT_EQ(ha, hb);  // THEN the rest is untouched
      continue;
    }
    ++inside;
    if (std::abs(std::remainder(ha - hb, 2.0 * M_PI)) > 0.3) ++far;
  }
  // THEN most garbage values are far from the truth (uniform over the circle: 90 % beyond 0.3 rad)
  EXPECT_GT(far, inside * 7 / 10);
}

TEST(SimFaultKinds, GarbageOnTheCameraFlagsTheTick) {
  std::vector<SimEvent> ticks = ofStream(
      runAll(withFault(fault(SimStream::kCamera, FaultKind::kGarbage, 2.0, 3.0)), kSeed), SimStream::kCamera);
  int corrupted = 0;
  for (const SimEvent& e : ticks) {
    const bool c = std::get<CameraTick>(e.sample).corrupted;
    EXPECT_EQ(c, inWindow(e.t_us, 2.0, 3.0)) << e.t_us;
    corrupted += c;
  }
  EXPECT_EQ(corrupted, 10);  // 1 s at 10 Hz
}

TEST(SimFaultKinds, SlowKeepsOneSampleInDivisor) {
  FaultSpec f = fault(SimStream::kDvl, FaultKind::kSlow, 4.0, 10.0);
  f.divisor = 5;
  const std::vector<SimEvent> a = cleanStream(SimStream::kDvl);
  const std::vector<SimEvent> b = ofStream(runAll(withFault(f), kSeed), SimStream::kDvl);
  // 6 s at 5 Hz = 30 samples due, 6 kept
  EXPECT_EQ(a.size(), b.size() + 24);
  int kept = 0;
  for (const SimEvent& e : b) kept += inWindow(e.t_us, 4.0, 10.0);
  EXPECT_EQ(kept, 6);
}

TEST(SimFaultKinds, IntermittentAlternatesBurstsAndSilences) {
  FaultSpec f = fault(SimStream::kDepth, FaultKind::kIntermittent, 5.0, 11.0);
  f.on_s = 0.5;
  f.off_s = 1.5;
  const std::vector<SimEvent> b = ofStream(runAll(withFault(f), kSeed), SimStream::kDepth);
  int kept = 0;
  for (const SimEvent& e : b) {
    if (!inWindow(e.t_us, 5.0, 11.0)) continue;
    ++kept;
    // Phase in integer microseconds: in floating point, t * 1e-6 - 5.0 at t = 7 s is 2.0 on x86-64 but
    // 1.9999999999999998 on aarch64 (g++ contracts it into one fused multiply-add there).
    EXPECT_LE((e.t_us - 5'000'000) % 2'000'000, 500'000) << e.t_us;
  }
  EXPECT_EQ(kept, 15);  // 3 bursts of 0.5 s at 10 Hz
}

TEST(SimFaultKinds, ClockJumpShiftsStampsNotArrivals) {
  FaultSpec f = fault(SimStream::kCompass, FaultKind::kClockJump, 6.0, 9.0);
  f.offset_ms = -750.0;
  const std::vector<SimEvent> all = runAll(withFault(f), kSeed);
  for (std::size_t i = 1; i < all.size(); ++i) ASSERT_LE(all[i - 1].t_us, all[i].t_us) << i;
  const std::vector<SimEvent> a = cleanStream(SimStream::kCompass);
  const std::vector<SimEvent> b = ofStream(all, SimStream::kCompass);
  ASSERT_EQ(a.size(), b.size());
  // Each sample arrives when the clean one does (same content, same place in the stream); only the
  // stamp it carries jumps, inside the window.
  int shifted = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto& clean = std::get<HeadingSample>(a[i].sample);
    const auto& jumped = std::get<HeadingSample>(b[i].sample);
    EXPECT_EQ(jumped.heading_rad, clean.heading_rad) << i;
    EXPECT_EQ(b[i].t_us, a[i].t_us) << i;
    EXPECT_EQ(jumped.t_us - clean.t_us, inWindow(a[i].t_us, 6.0, 9.0) ? -750000 : 0) << a[i].t_us;
    shifted += jumped.t_us != clean.t_us;
  }
  EXPECT_EQ(shifted, 30);  // 3 s at 10 Hz
}

TEST(SimFaultKinds, RejectsBadParameters) {
  FaultSchedule schedule;
  std::string error;
  FaultSpec f = fault(SimStream::kDvl, FaultKind::kSlow, 1.0, 2.0);
  f.divisor = 0;
  EXPECT_FALSE(schedule.init({f}, &error));
  f = fault(SimStream::kDvl, FaultKind::kIntermittent, 1.0, 2.0);
  f.on_s = 0.0;
  EXPECT_FALSE(schedule.init({f}, &error));
}

}  // namespace
}  // namespace deepnav::sim
