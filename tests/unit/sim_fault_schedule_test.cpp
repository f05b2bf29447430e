#include "tools/sim/faults/fault_schedule.h"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sim_test_events.h"
#include "sim_test_stats.h"
#include "tools/sim/rotation.h"

namespace deepnav::sim {
namespace {

using test::bitEqual;
using test::ofStream;
using test::fault;
using test::runAll;
using test::withFault;

constexpr std::uint64_t kSeed = 21;

bool inWindow(TimeUs t_us, double start_s, double end_s) { return t_us >= sToUs(start_s) && t_us < sToUs(end_s); }

TEST(SimFaultSchedule, DropoutRemovesTheWindowAndLeavesTheRestBitEqual) {
  const Scenario clean = withFault(fault(SimStream::kImu, FaultKind::kDropout, 100.0, 101.0));  // after the end
  const Scenario faulty = withFault(fault(SimStream::kDvl, FaultKind::kDropout, 5.0, 8.0));
  const std::vector<SimEvent> a = ofStream(runAll(clean, kSeed), SimStream::kDvl);
  const std::vector<SimEvent> b = ofStream(runAll(faulty, kSeed), SimStream::kDvl);
  ASSERT_EQ(a.size(), b.size() + 15);  // 3 s at 5 Hz
  std::size_t j = 0;
  for (const SimEvent& e : a) {
    if (inWindow(e.t_us, 5.0, 8.0)) continue;
    ASSERT_TRUE(bitEqual(e, b[j++])) << e.t_us;
  }
  SensorSimulator sim;
  std::string error;
  ASSERT_TRUE(sim.init(faulty, kSeed, &error));
  SimEvent e;
  while (sim.next(&e)) {
  }
  EXPECT_EQ(sim.dropped(SimStream::kDvl), 15u);
  EXPECT_EQ(sim.emitted(SimStream::kDvl), 86u);
}

TEST(SimFaultSchedule, DropoutProbabilityThinsTheStream) {
  FaultSpec f = fault(SimStream::kImu, FaultKind::kDropout, 0.0, 20.0);
  f.probability = 0.3;
  const std::size_t kept = ofStream(runAll(withFault(f), kSeed), SimStream::kImu).size();
  EXPECT_NEAR(static_cast<double>(kept) / 2001.0, 0.7, 0.05);
}

TEST(SimFaultSchedule, OutlierAddsTheConfiguredNumberOfSigmas) {
  FaultSpec f = fault(SimStream::kCompass, FaultKind::kOutlier, 5.0, 6.0);
  f.magnitude_sigma = 20.0;
  Scenario faulty = withFault(f);
  const std::vector<SimEvent> a = ofStream(runAll(withFault(fault(SimStream::kImu, FaultKind::kDropout, 99, 100)), kSeed),
                                           SimStream::kCompass);
  const std::vector<SimEvent> b = ofStream(runAll(faulty, kSeed), SimStream::kCompass);
  ASSERT_EQ(a.size(), b.size());
  const double sigma_rad = faulty.compass.noise_deg * kDegToRad;
  int hits = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double delta = wrapToPi(std::get<HeadingSample>(b[i].sample).heading_rad -
                                  std::get<HeadingSample>(a[i].sample).heading_rad);
    if (inWindow(a[i].t_us, 5.0, 6.0)) {
      EXPECT_NEAR(std::abs(delta), 20.0 * sigma_rad, 1e-9) << a[i].t_us;
      ++hits;
    } else {
      EXPECT_TRUE(bitEqual(a[i], b[i]));
    }
  }
  EXPECT_EQ(hits, 10);
}

TEST(SimFaultSchedule, OutlierOnTheImuHitsEveryAxis) {
  FaultSpec f = fault(SimStream::kImu, FaultKind::kOutlier, 2.0, 2.5);
  f.magnitude_sigma = 8.0;
  const Scenario scenario = withFault(f);
  SensorSimulator sim;
  std::string error;
  ASSERT_TRUE(sim.init(scenario, kSeed, &error));
  const double gyro_sigma = sim.imuModel().gyroNoiseSigma_radps();
  SimEvent e;
  while (sim.next(&e)) {
    if (e.stream != SimStream::kImu || !inWindow(e.t_us, 2.0, 2.5)) continue;
    const ImuSample& m = std::get<ImuSample>(e.sample);
    const Eigen::Vector3d w_true = sim.truthAt(e.t_us).w_robot_radps;
    // 8 sigma of outlier against < 5 sigma of noise plus a tiny bias: every axis is far off.
    for (int i = 0; i < 3; ++i) EXPECT_GT(std::abs(m.w_imu_radps[i] - w_true[i]), 2.5 * gyro_sigma);
  }
}

TEST(SimFaultSchedule, StuckRepeatsTheLastValueWithFreshStamps) {
  const std::vector<SimEvent> depth =
      ofStream(runAll(withFault(fault(SimStream::kDepth, FaultKind::kStuck, 5.0, 7.0)), kSeed), SimStream::kDepth);
  double last_before = 0.0;
  TimeUs previous_us = -1;
  int stuck = 0;
  for (const SimEvent& e : depth) {
    const auto& d = std::get<DepthSample>(e.sample);
    EXPECT_GT(e.t_us, previous_us);
    previous_us = e.t_us;
    if (e.t_us < sToUs(5.0)) last_before = d.pressure_pa;
    if (inWindow(e.t_us, 5.0, 7.0)) {
      EXPECT_EQ(d.pressure_pa, last_before);
      ++stuck;
    }
    if (e.t_us >= sToUs(7.0)) {
      EXPECT_NE(d.pressure_pa, last_before);
    }
  }
  EXPECT_EQ(stuck, 20);
}

TEST(SimFaultSchedule, TimeJitterMovesStampsNotContentAndKeepsOrder) {
  FaultSpec f = fault(SimStream::kImu, FaultKind::kTimeJitter, 5.0, 15.0);
  f.std_ms = 2.0;
  const std::vector<SimEvent> all = runAll(withFault(f), kSeed);
  for (std::size_t i = 1; i < all.size(); ++i) ASSERT_LE(all[i - 1].t_us, all[i].t_us) << i;
  // Stamp errors against the ground truth stamps (same instants, never jittered): match by content.
  const std::vector<SimEvent> jittered = ofStream(all, SimStream::kImu);
  const std::vector<SimEvent> clean =
      ofStream(runAll(withFault(fault(SimStream::kImu, FaultKind::kDropout, 99, 100)), kSeed), SimStream::kImu);
  ASSERT_EQ(jittered.size(), clean.size());
  std::vector<double> jitter_ms;
  for (const SimEvent& c : clean) {
    // Jitter can reorder IMU samples among themselves: find the one with the same content.
    const ImuSample& cm = std::get<ImuSample>(c.sample);
    const SimEvent* match = nullptr;
    for (const SimEvent& j : jittered)
      if (std::get<ImuSample>(j.sample).w_imu_radps == cm.w_imu_radps) match = &j;
    ASSERT_NE(match, nullptr);
    const double d_ms = (match->t_us - c.t_us) * 1e-3;
    if (inWindow(c.t_us, 5.0, 15.0)) {
      jitter_ms.push_back(d_ms);
      EXPECT_LE(std::abs(d_ms), 8.0);
    } else {
      EXPECT_EQ(d_ms, 0.0);
    }
  }
  ASSERT_EQ(jitter_ms.size(), 1000u);
  EXPECT_NEAR(test::stddev(jitter_ms) / 2.0, 1.0, 0.1);
}

TEST(SimFaultSchedule, RejectsAnEmptyWindowAndGroundTruthFaults) {
  FaultSchedule schedule;
  std::string error;
  EXPECT_FALSE(schedule.init({fault(SimStream::kImu, FaultKind::kDropout, 5.0, 5.0)}, &error));
  EXPECT_FALSE(schedule.init({fault(SimStream::kGroundTruth, FaultKind::kDropout, 1.0, 2.0)}, &error));
  EXPECT_NE(error.find("faults[0]"), std::string::npos);
}

}  // namespace
}  // namespace deepnav::sim
