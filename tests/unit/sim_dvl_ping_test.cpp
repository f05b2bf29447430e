// The DVL's altitude window (dropout rate near its edges) and its altitude-dependent ping rate, in the
// model and through the SensorSimulator.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "sim_test_dvl.h"
#include "sim_test_stats.h"
#include "tools/sim/rotation.h"
#include "tools/sim/sensor_simulator.h"
#include "tools/sim/sensors/dvl_model.h"

namespace deepnav::sim {
namespace {

using test::makeDvl;
using test::noiselessDvlConfig;
using test::restingState;

DvlConfig beamModel() {
  DvlConfig c = noiselessDvlConfig();
  c.beam_noise_floor_mps = 0.001;
  return c;
}

constexpr std::uint64_t kDvlSeed = 5;

double normalCdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// Level at the window's edge, each beam's vertical range is h + n cos(a), n ~ N(0, range sigma): a beam
// locks with probability p = Phi((max - h) / (sigma cos a)) (or Phi((h - min) / ...) at the lower edge),
// independently, and the ensemble is valid with >= 3 beams: p^4 + 4 p^3 (1 - p). 4000 pings: standard
// errors 0.004 (beam fraction) and 0.0075 (valid fraction); 0.02 and 0.03 allowed.
TEST(SimDvlWindow, DropoutRateNearTheAltitudeWindowFollowsTheRangeNoise) {
  DvlConfig c = beamModel();
  c.range_noise_m = 0.05;
  c.min_altitude_m = 1.0;
  c.max_altitude_m = 5.0;
  const double sigma_vertical = 0.05 * std::cos(30.0 * kDegToRad);
  struct Case {
    double height_m;
    double p_lock;
  };
  for (const Case& k : {Case{5.0, 0.5}, Case{5.0 - sigma_vertical, normalCdf(1.0)},
                        Case{1.0 + 0.5 * sigma_vertical, normalCdf(0.5)}, Case{3.0, 1.0}, Case{5.3, 0.0}}) {
    DvlModel dvl = makeDvl(c, kDvlSeed);
    const KinematicState s = restingState(k.height_m);
    constexpr int kPings = 4000;
    int beams = 0, valid = 0;
    for (int i = 0; i < kPings; ++i) {
      const DvlSample m = dvl.measure(s, TimeUs{i} * 100000);
      for (int b = 0; b < 4; ++b) beams += (m.beam_valid_mask >> b) & 1;
      valid += m.valid;
    }
    const double p = k.p_lock;
    EXPECT_NEAR(beams / (4.0 * kPings), p, 0.02) << k.height_m;
    EXPECT_NEAR(static_cast<double>(valid) / kPings, std::pow(p, 4) + 4.0 * std::pow(p, 3) * (1.0 - p), 0.03)
        << k.height_m;
  }
}

// Pings counted over 20 s of 100 Hz channel ticks at a constant altitude. Period = max(1 / 20 Hz,
// 2 slant / 1500 m/s + 30 ms), quantised up to whole 10 ms ticks: 1 m: 31.5 ms -> 50 ms (the cap);
// 30 m: 76.2 ms -> 80 ms; 60 m: 122.4 ms -> 130 ms; 150 m (out of the 100 m window, listening over all
// of it, 115.5 m slant): 184.0 ms -> 190 ms.
TEST(SimDvlPingRate, PingsSlowerAtHigherAltitude) {
  DvlConfig c = beamModel();
  c.max_altitude_m = 100.0;
  c.max_ping_rate_hz = 20.0;
  c.ping_processing_ms = 30.0;
  EXPECT_NEAR(DvlPingTiming::period_s(30.0 / std::cos(30.0 * kDegToRad), 20.0, 0.03), 0.0761880, 1e-6);
  struct Case {
    double height_m;
    int period_ticks;
  };
  constexpr int kTicks = 2000;
  double previous_rate_hz = 1e9;
  for (const Case& k : {Case{1.0, 5}, Case{30.0, 8}, Case{60.0, 13}, Case{150.0, 19}}) {
    DvlModel dvl = makeDvl(c, kDvlSeed);
    const KinematicState s = restingState(k.height_m);
    int pings = 0;
    for (int i = 0; i <= kTicks; ++i) {
      const TimeUs t_us = std::llround(i * 1e6 / 100.0);
      if (!dvl.pingDue(t_us)) continue;
      dvl.measure(s, t_us);
      ++pings;
    }
    EXPECT_EQ(pings, kTicks / k.period_ticks + 1) << k.height_m;
    const double rate_hz = pings / 20.0;
    EXPECT_LT(rate_hz, previous_rate_hz);
    previous_rate_hz = rate_hz;
  }
}

// The default dive with the channel at 50 Hz and a 50 Hz cap: at 1.2-1.7 m the period is 30 ms + ~3 ms,
// so the instrument pings every second tick (40 ms): 3001 ensembles of 6001 ticks, the others counted
// as not pinged (not as fault drops).
TEST(SimDvlPingRate, SimulatorEmitsOnlyWhenAPingIsDue) {
  Scenario scenario;
  scenario.dvl.rate_hz = 50.0;
  scenario.dvl.max_ping_rate_hz = 50.0;
  SensorSimulator sim;
  std::string error;
  ASSERT_TRUE(sim.init(scenario, 1, &error)) << error;
  SimEvent e;
  TimeUs last_us = -1;
  while (sim.next(&e)) {
    if (e.stream != SimStream::kDvl) continue;
    if (last_us >= 0) {
      EXPECT_EQ(e.t_us - last_us, 40000);
    }
    last_us = e.t_us;
  }
  EXPECT_EQ(sim.emitted(SimStream::kDvl), 3001u);
  EXPECT_EQ(sim.notPinged(SimStream::kDvl), 3000u);
  EXPECT_EQ(sim.dropped(SimStream::kDvl), 0u);
}

}  // namespace
}  // namespace deepnav::sim
