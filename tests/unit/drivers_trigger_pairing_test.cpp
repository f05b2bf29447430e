// Software-triggered stereo pairing under delays and losses: a deterministic simulation of two
// cameras, their trigger threads and the driver thread feeding TriggerTracker and FramePairer exactly
// as AravisStereoCamera does. The root cause of the mixed pairs seen under CPU load is reproduced with
// timestamp-only pairing, and never happens with trigger ticks.
#include <algorithm>
#include <cstdint>
#include <map>
#include <queue>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/camera/frame_pairer.h"
#include "drivers/camera/trigger_tracker.h"

namespace deepnav {
namespace {

constexpr TimeUs kPeriodUs = 50'000;     // 20 Hz
constexpr TimeUs kToleranceUs = 10'000;  // camera.pair_tolerance_ms

TEST(TriggerTracker, OneOutstandingTriggerAnsweredByTheNextFrame) {
  TriggerTracker t;
  t.configure(4 * kPeriodUs, 2 * kPeriodUs);
  EXPECT_TRUE(t.beginTrigger(0, 0));
  EXPECT_FALSE(t.beginTrigger(1, 50'000));  // unanswered: tick 1 skipped
  EXPECT_EQ(t.onFrame(60'000), 0);
  EXPECT_TRUE(t.beginTrigger(2, 100'000));
  EXPECT_EQ(t.onFrame(120'000), 2);
  EXPECT_EQ(t.onFrame(130'000), -1);  // a frame with no trigger outstanding
  EXPECT_EQ(t.counts().skipped, 1u);
  EXPECT_EQ(t.counts().unattributed, 1u);
}

TEST(TriggerTracker, AnAbandonedTriggersLateFrameIsNotTakenForTheNextTrigger) {
  TriggerTracker t;
  t.configure(4 * kPeriodUs, 2 * kPeriodUs);
  EXPECT_TRUE(t.beginTrigger(0, 0));
  for (int g = 1; g <= 3; ++g) EXPECT_FALSE(t.beginTrigger(g, g * kPeriodUs));
  EXPECT_FALSE(t.beginTrigger(4, 200'000));  // tick 0 abandoned after 200 ms: quiet until 300 ms
  EXPECT_EQ(t.counts().timeouts, 1u);
  EXPECT_FALSE(t.beginTrigger(5, 250'000));
  EXPECT_EQ(t.onFrame(260'000), -1);        // its late frame: the line is clean again
  EXPECT_TRUE(t.beginTrigger(6, 300'000));
  EXPECT_EQ(t.onFrame(303'000), 6);
}

TEST(TriggerTracker, AnIncompleteFrameHandedOverAfterTheNextTriggerIsNotItsAnswer) {
  TriggerTracker t;
  t.configure(4 * kPeriodUs, 2 * kPeriodUs);
  EXPECT_TRUE(t.beginTrigger(0, 0));
  EXPECT_FALSE(t.beginTrigger(4, 200'000));  // abandoned; no frame comes while the line is quiet
  EXPECT_TRUE(t.beginTrigger(6, 300'000));
  // Tick 0's frame lost packets: its leader arrived at 5 ms, the stream hands it over only now that
  // tick 6's packets arrive. Not tick 6's answer, and tick 6 stays outstanding.
  EXPECT_EQ(t.onFrame(5'000), -1);
  EXPECT_EQ(t.outstanding(), 6);
  EXPECT_EQ(t.onFrame(304'000), 6);
}

TEST(TriggerTracker, AFailedTriggerWriteIsAbandoned) {
  TriggerTracker t;
  t.configure(4 * kPeriodUs, 2 * kPeriodUs);
  EXPECT_TRUE(t.beginTrigger(0, 0));
  t.triggerFailed(1'000);
  EXPECT_FALSE(t.beginTrigger(1, 50'000));  // its frame may still come
  EXPECT_TRUE(t.beginTrigger(3, 150'000));
}

TEST(FramePairer, TickedFramesPairOnlyWithTheSameTick) {
  FramePairer p(kToleranceUs);
  EXPECT_FALSE(p.offer(1, 100'000, 1, 1).paired);  // right frame of tick 1, late
  // The left frame of tick 2 is within tolerance of it in time, but of another trigger.
  auto r = p.offer(0, 104'000, 2, 2);
  EXPECT_FALSE(r.paired);
  ASSERT_EQ(r.dropped_count, 1);  // right tick 1 can never pair now
  EXPECT_EQ(r.dropped[0].handle, 1);
  r = p.offer(1, 106'000, 3, 2);
  ASSERT_TRUE(r.paired);
  EXPECT_EQ(r.left.handle, 2);
  EXPECT_EQ(r.right.handle, 3);
}

TEST(FramePairer, FramesOfOneTickTooFarApartAreBothDropped) {
  FramePairer p(kToleranceUs);
  p.offer(0, 100'000, 1, 5);
  const auto r = p.offer(1, 140'000, 2, 5);
  EXPECT_FALSE(r.paired);
  EXPECT_EQ(r.dropped_count, 2);
  EXPECT_EQ(p.pending(0) + p.pending(1), 0);
}

TEST(FramePairer, AFrameBehindTheOtherSideIsDroppedAtOnce) {
  FramePairer p(kToleranceUs);
  p.offer(0, 200'000, 1, 4);
  const auto r = p.offer(1, 201'000, 2, 3);
  EXPECT_FALSE(r.paired);
  ASSERT_EQ(r.dropped_count, 1);
  EXPECT_EQ(r.dropped[0].handle, 2);
  EXPECT_EQ(p.pending(0), 1);
}

// --- simulation ----------------------------------------------------------------------------------

struct SimConfig {
  int ticks = 4000;
  double p_late_trigger = 0.0;   // trigger thread woken late (load)
  TimeUs late_trigger_max_us = 0;
  double p_late_frame = 0.0;     // frame delayed between camera and driver (camera thread, receive thread, driver thread)
  TimeUs late_frame_max_us = 0;
  double p_lost = 0.0;           // frame never arrives
  double p_bad = 0.0;            // frame arrives with a bad status (answers the trigger, never paired)
  bool use_ticks = true;         // false: the former timestamp-only pairing
  std::uint32_t seed = 1;
};

struct SimResult {
  int pairs = 0, mixed = 0, dropped = 0, unattributed = 0, skipped = 0;
};

SimResult simulate(const SimConfig& c) {
  std::mt19937 rng(c.seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto chance = [&](double p) { return u(rng) < p; };
  auto upTo = [&](TimeUs max_us) { return static_cast<TimeUs>(u(rng) * static_cast<double>(max_us)); };

  // Events in time order: trigger writes and frame arrivals at the driver thread.
  struct Event {
    TimeUs t_us;
    int kind;  // 0: trigger write, 1: frame taken by the driver thread
    int side;
    std::int64_t tick;  // trigger: the tick; frame: the true tick that made it
    TimeUs arrival_us;  // frame: leader packet arrival
    bool good;
    bool operator>(const Event& o) const { return t_us > o.t_us || (t_us == o.t_us && kind > o.kind); }
  };
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events;
  for (int g = 0; g < c.ticks; ++g) {
    for (int side = 0; side < 2; ++side) {
      const TimeUs late = chance(c.p_late_trigger) ? upTo(c.late_trigger_max_us) : upTo(500);
      events.push({g * kPeriodUs + late, 0, side, g, 0, true});
    }
  }
  std::array<TriggerTracker, 2> trackers;
  for (auto& t : trackers) t.configure(4 * kPeriodUs, 2 * kPeriodUs);
  std::array<TimeUs, 2> last_taken_us{0, 0};  // a camera's frames reach the driver in order
  FramePairer pairer(kToleranceUs);
  pairer.setMaxPending(4);
  std::map<int, std::int64_t> true_tick;  // handle -> the tick that really made the frame
  int next_handle = 0;
  SimResult r;
  while (!events.empty()) {
    const Event e = events.top();
    events.pop();
    auto& tracker = trackers[static_cast<std::size_t>(e.side)];
    if (e.kind == 0) {
      if (c.use_ticks && !tracker.beginTrigger(e.tick, e.t_us)) continue;
      // The camera exposes 1-3 ms after the write; the frame may be lost or delayed on its way.
      if (chance(c.p_lost)) continue;
      const TimeUs exposure_us = e.t_us + 1'000 + upTo(2'000);
      const TimeUs arrival_us = exposure_us + 3'000 + upTo(1'000) + (chance(c.p_late_frame) ? upTo(c.late_frame_max_us) : 0);
      const TimeUs taken_us = std::max(arrival_us + upTo(300), last_taken_us[static_cast<std::size_t>(e.side)]);
      last_taken_us[static_cast<std::size_t>(e.side)] = taken_us;
      events.push({taken_us, 1, e.side, e.tick, arrival_us, !chance(c.p_bad)});
      continue;
    }
    const std::int64_t tick = c.use_ticks ? tracker.onFrame(e.arrival_us) : -1;
    if (!e.good || (c.use_ticks && tick < 0)) continue;
    const int handle = next_handle++;
    true_tick[handle] = e.tick;
    const FramePairer::Result p = pairer.offer(e.side, e.arrival_us, handle, tick);
    r.dropped += p.dropped_count;
    if (p.paired) {
      ++r.pairs;
      r.mixed += true_tick[p.left.handle] != true_tick[p.right.handle];
    }
  }
  for (const auto& t : trackers) {
    r.unattributed += static_cast<int>(t.counts().unattributed);
    r.skipped += static_cast<int>(t.counts().skipped);
  }
  return r;
}

TEST(TriggerPairingSimulation, QuietHostPairsEveryTrigger) {
  SimConfig c;
  c.ticks = 1000;
  const SimResult r = simulate(c);
  EXPECT_EQ(r.pairs, 1000);
  EXPECT_EQ(r.mixed, 0);
  EXPECT_EQ(r.dropped + r.unattributed + r.skipped, 0);
}

SimConfig loaded(std::uint32_t seed) {
  SimConfig c;
  c.seed = seed;
  c.p_late_trigger = 0.05;
  c.late_trigger_max_us = 120'000;
  c.p_late_frame = 0.10;
  c.late_frame_max_us = 200'000;
  c.p_lost = 0.01;
  c.p_bad = 0.02;
  return c;
}

// The root cause: a frame delayed by more than the period minus the tolerance lands within tolerance
// of the other camera's frame of the next trigger, and timestamp pairing takes them for a pair.
TEST(TriggerPairingSimulation, TimestampPairingMixesTriggersUnderLoad) {
  SimConfig c = loaded(7);
  c.use_ticks = false;
  const SimResult r = simulate(c);
  std::printf("timestamp pairing under load: %d pairs, %d mixed\n", r.pairs, r.mixed);
  EXPECT_GT(r.mixed, 0);
}

// With trigger ticks, over 10 seeds x 4000 triggers of delays up to 4 periods, losses and bad frames:
// no mixed pair; the frames that cannot be attributed are dropped and counted instead.
TEST(TriggerPairingSimulation, TickPairingNeverMixesTriggersUnderLoad) {
  SimResult total;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    const SimResult r = simulate(loaded(seed));
    total.pairs += r.pairs, total.mixed += r.mixed, total.dropped += r.dropped;
    total.unattributed += r.unattributed, total.skipped += r.skipped;
  }
  std::printf("tick pairing under load: %d pairs of 40000 triggers, %d mixed, %d dropped by the pairer, "
              "%d unattributed, %d ticks skipped\n",
              total.pairs, total.mixed, total.dropped, total.unattributed, total.skipped);
  EXPECT_EQ(total.mixed, 0);
  // A tenth of the frames are late by up to 4 periods: a late frame's pair is out of tolerance and its
  // camera skips ticks until it is answered. Timestamp pairing keeps 55 % of the ticks here (8 % of
  // its pairs mixed), tick pairing 45 % (none mixed).
  EXPECT_GT(total.pairs, 16000);
}

// Beyond the documented bound: frames stamped up to 1 s late (20 periods, far past timeout + quiet).
// The residual mixing is measured, not assumed away: over 5 seeds, 25 mixed of 3336 pairs with ticks
// against 323 of 3076 with timestamps only.
TEST(TriggerPairingSimulation, FramesLaterThanTheBoundAreTheResidualRisk) {
  SimResult ticks, times;
  for (std::uint32_t seed = 1; seed <= 5; ++seed) {
    SimConfig c = loaded(seed);
    c.late_frame_max_us = 1'000'000;
    const SimResult r = simulate(c);
    ticks.pairs += r.pairs, ticks.mixed += r.mixed;
    c.use_ticks = false;
    const SimResult t = simulate(c);
    times.pairs += t.pairs, times.mixed += t.mixed;
  }
  std::printf("frames up to 1 s late: tick pairing %d pairs, %d mixed; timestamp pairing %d pairs, %d mixed\n",
              ticks.pairs, ticks.mixed, times.pairs, times.mixed);
  EXPECT_LT(ticks.mixed * 5, times.mixed);
}

}  // namespace
}  // namespace deepnav
