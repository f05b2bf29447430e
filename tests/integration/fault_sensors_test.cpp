// Fault injection on replay, navigation sensors (issue #9 item 1): sensor-only dives of the default
// scenario (no rendering) with the simulator's fault schedules, replayed through the bench replay (the
// vehicle's NavCore) with the fault injector tapped in. Each case compares the faulted run with the
// clean run of the same dive (same seed: the clean samples are bit-identical), asserts what must hold
// and prints its figure on a `[fault]` line.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "tests/support/fault_replay.h"

namespace deepnav {
namespace {

using testing::FaultRun;
using testing::faultySamples;
using testing::firstClear;
using testing::firstFlagged;
using testing::maxDeviation;
using testing::nonFiniteTicks;
using testing::replayWithFaults;
using testing::sensorDive;
using testing::strf;
using testing::tickAt;

constexpr double kDive_s = 30.0;

struct Sensor {
  const char* stream;   // scenario name
  NavSource source;
  InputKind input_kind;
  double period_s;      // sample period in the default scenario
  double timeout_s;     // the board's stale timeout
};

const Sensor kDvl{"dvl", kSrcDvl, InputKind::kDvl, 0.2, 1.0};
const Sensor kCompass{"compass", kSrcHeading, InputKind::kHeading, 0.1, 1.0};
const Sensor kAttitude{"attitude", kSrcAttitude, InputKind::kAttitude, 0.1, 1.0};
const Sensor kDepth{"depth", kSrcDepth, InputKind::kDepth, 0.1, 1.0};
const Sensor kImu{"imu", kSrcImu, InputKind::kImu, 0.01, 0.05};

std::string fault(const Sensor& s, const std::string& kind, double t0, double t1, const std::string& params = "") {
  if (params.empty()) return strf("[{stream: %s, kind: %s, t_start_s: %.3f, t_end_s: %.3f}]", s.stream, kind.c_str(), t0, t1);
  return strf("[{stream: %s, kind: %s, t_start_s: %.3f, t_end_s: %.3f, params: {%s}}]", s.stream, kind.c_str(), t0, t1,
              params.c_str());
}

const std::string& cleanDive() {
  static const std::string path = sensorDive("clean", "[]", kDive_s);
  return path;
}

const FaultRun& cleanRun() {
  static const FaultRun run = replayWithFaults(cleanDive(), "clean");
  return run;
}

TEST(FaultSensors, StoppedSensorIsFlaggedWithinItsTimeoutAndRefusesCleanly) {
  for (const Sensor& s : {kDvl, kCompass, kAttitude, kDepth, kImu}) {
    SCOPED_TRACE(s.stream);
    // GIVEN the sensor stopped from 12 to 17 s
    const double stop_s = 12.0, resume_s = 17.0;
    const FaultRun run = replayWithFaults(
        sensorDive(strf("stop_%s", s.stream), fault(s, "dropout", stop_s, resume_s), kDive_s), strf("stop_%s", s.stream));
    // THEN every output is finite
    EXPECT_EQ(nonFiniteTicks(run), 0);
    // AND the stale bit rises one timeout after the last sample, and not before
    const double last_sample_s = stop_s - s.period_s;
    const double flagged_s = firstFlagged(run, staleBit(s.source), last_sample_s);
    ASSERT_GE(flagged_s, 0.0) << "never flagged stale";
    const double latency_s = flagged_s - last_sample_s;
    EXPECT_GE(latency_s, s.timeout_s);
    EXPECT_LE(latency_s, s.timeout_s + 0.011);
    EXPECT_LT(firstFlagged(cleanRun(), staleBit(s.source), 1.0), 0.0) << "the clean run flags it too";
    // AND it clears with the first sample after the resumption
    const double cleared_s = firstClear(run, staleBit(s.source), resume_s);
    ASSERT_GE(cleared_s, 0.0);
    EXPECT_LE(cleared_s - resume_s, 0.011);
    // AND the drift while it was away is within the filter's own 3 sigma, corrected on re-fusion
    const TickRecord& before = tickAt(run, resume_s - 0.01);
    const TickRecord& clean_before = tickAt(cleanRun(), resume_s - 0.01);
    const double drift_m = (before.p_robot_in_odom_m - clean_before.p_robot_in_odom_m).norm();
    const double sigma_m = before.position_sigma_m;
    const double after_m = maxDeviation(run, cleanRun(), resume_s + 2.0, resume_s + 2.0).position_m;
    const double step_sigma = std::abs(drift_m - after_m) / sigma_m;
    double max_tick_step_m = 0.0;  // largest tick-to-tick jump of the published position beyond the clean run's
    for (double t = resume_s; t < resume_s + 2.0; t += 0.01) {
      const Eigen::Vector3d df = tickAt(run, t + 0.01).p_robot_in_odom_m - tickAt(run, t).p_robot_in_odom_m;
      const Eigen::Vector3d dc = tickAt(cleanRun(), t + 0.01).p_robot_in_odom_m - tickAt(cleanRun(), t).p_robot_in_odom_m;
      max_tick_step_m = std::max(max_tick_step_m, (df - dc).norm());
    }
    EXPECT_LT(drift_m, 3.0 * sigma_m);
    EXPECT_LT(max_tick_step_m, 0.02);
    std::printf("[fault] %s stopped %.0f-%.0f s: stale after %.3f s (timeout %.2f s), cleared %.3f s after resuming; "
                "drift %.4f m = %.2f sigma, re-fusion step %.2f sigma, max tick step %.2f mm\n",
                s.stream, stop_s, resume_s, latency_s, s.timeout_s, cleared_s - resume_s, drift_m, drift_m / sigma_m,
                step_sigma, max_tick_step_m * 1e3);
  }
}

TEST(FaultSensors, OutliersOf5To50SigmaAreRejected) {
  for (const Sensor& s : {kDvl, kCompass, kAttitude, kDepth}) {
    for (double k : {5.0, 10.0, 20.0, 50.0}) {
      SCOPED_TRACE(strf("%s %.0f", s.stream, k));
      // GIVEN one sample in four hit by a k-sigma outlier on every component from 8 to 28 s
      const std::string name = std::string("outlier_") + s.stream + std::to_string(int(k));
      const FaultRun run = replayWithFaults(
          sensorDive(name, fault(s, "outlier", 8.0, 28.0, strf("probability: 0.25, magnitude_sigma: %.1f", k)), kDive_s),
          name);
      // THEN the outliers are there, and none (>= 10 sigma) or almost none (5 sigma: the noise can pull
      // one back under the 3-sigma gate) is accepted
      const testing::FaultySamples f = faultySamples(cleanRun(), run, s.input_kind);
      EXPECT_GT(f.faulty, 10);
      if (k >= 10.0) {
        EXPECT_EQ(f.accepted, 0);
      } else {
        EXPECT_LE(f.accepted, f.faulty / 10);
      }
      EXPECT_EQ(nonFiniteTicks(run), 0);
      const testing::Deviation d = maxDeviation(run, cleanRun());
      EXPECT_LT(d.position_m, 0.02);
      EXPECT_LT(d.angle_rad, 0.2 * M_PI / 180.0);
      std::printf("[fault] %s outlier %2.0f sigma: %d outliers, false accepts %d, max deviation %.4f m %.3f deg\n",
                  s.stream, k, f.faulty, f.accepted, d.position_m, d.angle_rad * 180.0 / M_PI);
    }
  }
}

// The same dive with the sensor simply missing from t0 to t1: what a refused stream must not be worse than.
const FaultRun& dropoutRun(const Sensor& s, double t0, double t1) {
  static std::map<std::string, FaultRun> runs;
  const std::string name = strf("drop_%s_%.0f_%.0f", s.stream, t0, t1);
  auto it = runs.find(name);
  if (it == runs.end()) it = runs.emplace(name, replayWithFaults(sensorDive(name, fault(s, "dropout", t0, t1), kDive_s), name)).first;
  return it->second;
}

// A refused stream is no worse than a missing one, give or take what the samples fused before the fault
// is recognised can do (a stuck stream is only recognised after ekf.stuck_after_samples repeats).
void expectNoWorseThanMissing(const testing::Deviation& d, const testing::Deviation& missing, double slack_m = 0.005,
                              double slack_deg = 0.05) {
  EXPECT_LE(d.position_m, 1.2 * missing.position_m + slack_m);
  EXPECT_LE(d.angle_rad, 1.2 * missing.angle_rad + slack_deg * M_PI / 180.0);
}

// Time from t_start_s to the first tick with the source's stale or reject bit; -1: never flagged.
double timeToFlag(const FaultRun& run, const Sensor& s, double t_start_s, double t_end_s) {
  const double t = firstFlagged(run, staleBit(s.source) | rejectBit(s.source), t_start_s, t_end_s + s.timeout_s + 0.1);
  return t < 0.0 ? -1.0 : t - t_start_s;
}

TEST(FaultSensors, StuckGarbageSlowAndIntermittentStreams) {
  struct Case {
    Sensor sensor;
    const char* kind;
    const char* params;
    bool must_flag;
  };
  // Slow: the DVL at a fifth of its rate (1 Hz, samples 1 s apart: not stale with a 1 s timeout) and at
  // a tenth (2 s apart: stale between samples). Intermittent: 0.5 s bursts, 2 s silences.
  const std::vector<Case> cases = {
      {kDvl, "garbage", "", true},          {kCompass, "garbage", "", true},
      {kDepth, "garbage", "", true},        {kAttitude, "garbage", "", true},
      {kDvl, "stuck", "", false},           {kCompass, "stuck", "", false},
      {kDepth, "stuck", "", false},         {kDvl, "slow", "divisor: 5", false},
      {kDvl, "slow", "divisor: 10", true},  {kCompass, "slow", "divisor: 20", true},
      {kDvl, "intermittent", "on_s: 0.5, off_s: 2.0", true},
      {kDepth, "intermittent", "on_s: 0.5, off_s: 2.0", true},
  };
  const double t0 = 10.0, t1 = 20.0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const std::string name = strf("%s_%s%zu", c.sensor.stream, c.kind, i);
    SCOPED_TRACE(name);
    // GIVEN the stream faulty from 10 to 20 s
    const FaultRun run = replayWithFaults(sensorDive(name, fault(c.sensor, c.kind, t0, t1, c.params), kDive_s), name);
    // THEN the outputs stay finite, garbage is (almost) never accepted, and the error stays bounded
    EXPECT_EQ(nonFiniteTicks(run), 0);
    const testing::FaultySamples f = faultySamples(cleanRun(), run, c.sensor.input_kind);
    if (std::string(c.kind) == "garbage") {
      EXPECT_GT(f.faulty, 40);
      EXPECT_LE(f.accepted, f.faulty / 50 + 1);
    }
    const testing::Deviation d = maxDeviation(run, cleanRun());
    const testing::Deviation missing = maxDeviation(dropoutRun(c.sensor, t0, t1), cleanRun());
    if (std::string(c.kind) == "garbage") expectNoWorseThanMissing(d, missing);
    if (std::string(c.kind) == "stuck") expectNoWorseThanMissing(d, missing, 0.02, 0.15);
    // AND the fault is flagged (stale or rejected) where it must be
    const double flag_s = timeToFlag(run, c.sensor, t0, t1);
    if (c.must_flag) {
      EXPECT_GE(flag_s, 0.0) << "never flagged";
    }
    std::printf("[fault] %s %s%s%s%s: time to flag %s, faulty samples %d, accepted %d, max deviation %.4f m %.3f deg "
                "(stream missing instead: %.4f m %.3f deg)\n",
                c.sensor.stream, c.kind, c.params[0] ? " (" : "", c.params, c.params[0] ? ")" : "",
                flag_s < 0 ? "never" : strf("%.2f s", flag_s).c_str(), f.faulty, f.accepted,
                d.position_m, d.angle_rad * 180.0 / M_PI, missing.position_m, missing.angle_rad * 180.0 / M_PI);
  }
}

TEST(FaultSensors, FrozenImuIsRefusedAndCoastsAsInAnOutage) {
  // GIVEN the IMU repeating its last message (fresh stamps) from 12 to 17 s
  const double t0 = 12.0, t1 = 17.0;
  const FaultRun run = replayWithFaults(sensorDive("imu_stuck", fault(kImu, "stuck", t0, t1), kDive_s), "imu_stuck");
  // THEN it is flagged once the board's count of identical samples has come (ekf.imu_stuck_after_samples:
  // 10 at 100 Hz) plus the IMU's stale timeout, the outputs stay finite, and the estimate is no worse
  // than with the IMU silent over the same 5 s (the repeated samples are not integrated)
  EXPECT_EQ(nonFiniteTicks(run), 0);
  const double flag_s = timeToFlag(run, kImu, t0, t1);
  EXPECT_GE(flag_s, 0.0) << "never flagged";
  EXPECT_LE(flag_s, 10 * kImu.period_s + kImu.timeout_s + 0.02);
  const testing::Deviation d = maxDeviation(run, cleanRun());
  const testing::Deviation missing = maxDeviation(dropoutRun(kImu, t0, t1), cleanRun());
  expectNoWorseThanMissing(d, missing, 0.02, 0.15);
  // AND it is fused again after the fault
  const TickRecord& end = tickAt(run, kDive_s - 1.0);
  EXPECT_EQ(end.faults & (staleBit(kSrcImu) | rejectBit(kSrcImu)), 0u);
  std::printf("[fault] imu stuck 12-17 s: flagged %s, max deviation %.4f m %.3f deg (IMU silent instead: %.4f m %.3f deg)\n",
              flag_s < 0 ? "never" : strf("%.2f s after", flag_s).c_str(), d.position_m, d.angle_rad * 180.0 / M_PI,
              missing.position_m, missing.angle_rad * 180.0 / M_PI);
}

TEST(FaultSensors, ClockJumpsOfASensor) {
  struct Case {
    Sensor sensor;
    double offset_ms;
  };
  const std::vector<Case> cases = {{kDvl, 2000.0}, {kDvl, -2000.0}, {kCompass, 750.0}, {kCompass, -750.0},
                                   {kDepth, 5000.0}, {kImu, 300.0}, {kImu, -300.0}};
  const double t0 = 10.0, t1 = 15.0;
  for (const Case& c : cases) {
    const std::string name = std::string("jump_") + c.sensor.stream + std::to_string(int(c.offset_ms));
    SCOPED_TRACE(name);
    // GIVEN the sensor's stamps offset by offset_ms from 10 to 15 s (its clock jumped, then back)
    const FaultRun run = replayWithFaults(
        sensorDive(name, fault(c.sensor, "clock_jump", t0, t1, strf("offset_ms: %.1f", c.offset_ms)), kDive_s),
        name);
    // THEN the outputs stay finite, the estimate stays within half a metre and a degree of the clean
    // run's, and 10 s after the jump back the source is fused again (no lockout), its flags clear
    EXPECT_EQ(nonFiniteTicks(run), 0);
    const testing::Deviation d = maxDeviation(run, cleanRun());
    EXPECT_LT(d.position_m, 0.5);
    EXPECT_LT(d.angle_rad, 1.0 * M_PI / 180.0);
    // AND an aiding sensor's jumped samples are refused (stamped ahead of the loop's clock) or dropped
    // late (behind the delay window): it costs what 5 s without it cost (issue 21: a 2 s DVL jump at most
    // 0.1 m, 0.43 m before), and the jump is flagged while it lasts
    if (c.sensor.source != kSrcImu) {
      EXPECT_LT(d.position_m, 0.1);
      EXPECT_GE(timeToFlag(run, c.sensor, t0, t1), 0.0) << "never flagged";
    }
    const TickRecord& end = tickAt(run, kDive_s - 1.0);
    EXPECT_EQ(end.faults & (staleBit(c.sensor.source) | rejectBit(c.sensor.source)), 0u);
    EXPECT_EQ(end.faults & rejectBit(kSrcDvl), 0u) << "the DVL locked out";
    const double flag_s = timeToFlag(run, c.sensor, t0, t1 + std::abs(c.offset_ms) * 1e-3);
    std::printf("[fault] %s clock jump %+.0f ms for 5 s: flagged %s, dropped late %llu, bad input %llu, "
                "max deviation %.4f m %.3f deg\n",
                c.sensor.stream, c.offset_ms, flag_s < 0 ? "never" : strf("%.2f s after", flag_s).c_str(),
                static_cast<unsigned long long>(run.summary.inputs.dropped_late),
                static_cast<unsigned long long>(run.summary.inputs.bad_input), d.position_m, d.angle_rad * 180.0 / M_PI);
  }
}

TEST(FaultSensors, NonFiniteNegativeIndefiniteAndHugeCovariances) {
  const char* kValueNames[] = {"NaN", "Inf", "negative", "indefinite", "huge"};
  const char* kTargetNames[] = {"dvl", "depth", "heading", "attitude"};
  const std::string& dive = cleanDive();
  for (int target = 0; target < 4; ++target) {
    for (int value = 0; value < 5; ++value) {
      SCOPED_TRACE(strf("%s %s", kTargetNames[target], kValueNames[value]));
      // GIVEN every sample of the target from 10 to 20 s stating an unusable covariance (or sigma)
      InjectedFaultSpec spec;
      spec.kind = InjectedFault::kBadCovariance;
      spec.t_start_s = 10.0;
      spec.t_end_s = 20.0;
      spec.target = static_cast<CovarianceTarget>(target);
      spec.value = static_cast<CovarianceValue>(value);
      const FaultRun run = replayWithFaults(dive, std::string("cov_") + kTargetNames[target] + kValueNames[value], spec);
      // THEN no output is ever non-finite, no sample with a non-covariance is fused, and a huge one
      // changes nothing that matters
      EXPECT_EQ(nonFiniteTicks(run), 0);
      EXPECT_GT(run.tap->counters().injected, 40u);
      if (spec.value != CovarianceValue::kHuge) {
        EXPECT_EQ(run.tap->counters().accepted_injected, 0u);
      }
      const testing::Deviation d = maxDeviation(run, cleanRun());
      const Sensor& sensor = target == 0 ? kDvl : target == 1 ? kDepth : target == 2 ? kCompass : kAttitude;
      expectNoWorseThanMissing(d, maxDeviation(dropoutRun(sensor, 10.0, 20.0), cleanRun()));
      std::printf("[fault] %s covariance %s: %u samples, accepted %u, non-finite outputs %d, bad input %llu, "
                  "max deviation %.4f m %.3f deg\n",
                  kTargetNames[target], kValueNames[value], run.tap->counters().injected,
                  run.tap->counters().accepted_injected, nonFiniteTicks(run),
                  static_cast<unsigned long long>(run.summary.inputs.bad_input), d.position_m, d.angle_rad * 180.0 / M_PI);
    }
  }
}

}  // namespace
}  // namespace deepnav
