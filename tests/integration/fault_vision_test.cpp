// Fault injection on replay, cameras and vision results (issue #9 item 1). One short rendered dive that
// reaches stage 2 (as stage2_replay_test) with corrupted and missing camera frames from the simulator's
// fault schedule; its replay records every vision result the loop consumed, and that recording is then
// replayed again and again (no vision to recompute: fast) with the fault injector altering the marker
// and VO results: outliers, late, reordered, out of the fusion window, unusable covariances. Each case
// compares with the untouched replay, asserts what must hold and prints a `[fault]` line.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "nav/metrics/trajectory_association.h"
#include "tests/support/fault_replay.h"

namespace deepnav {
namespace {

using testing::FaultRun;
using testing::maxDeviation;
using testing::nonFiniteTicks;
using testing::replayWithFaults;

const std::vector<std::string> kQuickStages = {
    "stage.min_workspace_time_s=5", "stage.min_faces_seen_fraction=0.3", "vision.map_min_frames=6",
    "vision.map_min_voxels=300", "vision.map_every_n_frames=3"};

constexpr double kGarbageFrom_s = 30.0, kGarbageTo_s = 31.0;  // camera frames replaced by noise
constexpr double kMissingFrom_s = 33.0, kMissingTo_s = 35.0;  // camera frames missing

std::string dive() {
  return testing::makeTestDive(
      "vision_faults", 40.0, 11, true,
      {{"start_hold_s: 4.0", "start_hold_s: 1.0"},
       {"approach_s: 26.0", "approach_s: 8.0"},
       {"faults: []",
        "faults: [{stream: camera, kind: garbage, t_start_s: 30.0, t_end_s: 31.0}, "
        "{stream: camera, kind: dropout, t_start_s: 33.0, t_end_s: 35.0}]"}});
}

// Largest position error against the truth over [t0, t1).
double maxTruthError(const ReplaySummary& s, double t0, double t1) {
  const AssociatedTrajectories a = associateByTime(s.estimate, s.truth, 0.05);
  double e = 0.0;
  for (std::size_t i = 0; i < a.estimate.size(); ++i) {
    if (a.estimate[i].t_s < t0 || a.estimate[i].t_s >= t1) continue;
    e = std::max(e, (a.estimate[i].p_robot_in_odom_m - a.truth[i].p_robot_in_odom_m).norm());
  }
  return e;
}

std::uint32_t voAccepted(const FaultRun& r) {
  return r.summary.vo.accepted;
}

void cameraFaults(const FaultRun& base) {
  // THEN no marker, no VO comes out of a noise frame, the missing frames are missing, and the estimate
  // stays as good as before the faults
  int garbage = 0, missing_window = 0;
  for (const FrameStat& f : base.summary.frame_stats) {
    if (f.t_s >= kGarbageFrom_s && f.t_s < kGarbageTo_s) {
      ++garbage;
      EXPECT_EQ(f.markers, 0) << f.t_s;
      EXPECT_FALSE(f.orb_vo || f.planes_vo) << f.t_s;
    }
    if (f.t_s >= kMissingFrom_s && f.t_s < kMissingTo_s) ++missing_window;
  }
  EXPECT_EQ(garbage, 10);
  EXPECT_EQ(missing_window, 0);
  EXPECT_EQ(nonFiniteTicks(base), 0);
  const double before = maxTruthError(base.summary, 20.0, kGarbageFrom_s);
  const double during = maxTruthError(base.summary, kGarbageFrom_s, 40.0);
  EXPECT_LT(during, 0.15);
  int after_vo = 0;
  for (const FrameStat& f : base.summary.frame_stats) after_vo += f.t_s >= kMissingTo_s && (f.orb_vo || f.planes_vo);
  EXPECT_GT(after_vo, 5) << "VO never resumed after the missing frames";
  std::printf("[fault] camera: %d noise frames (0 markers, 0 VO from them), %d-s gap of missing frames; "
              "VO results after the gap %d; max error vs truth %.3f m before, %.3f m during and after\n",
              garbage, static_cast<int>(kMissingTo_s - kMissingFrom_s), after_vo, before, during);
}

// Replays with k-sigma outliers of one kind on every second result in [t_start_s, t_end_s] and checks what
// must hold: none accepted from 10 sigma (at most one in ten at 5), every output finite, the estimate within
// 5 cm of the clean run. Returns the run and its largest deviation for the printed figure.
FaultRun outlierRun(const std::string& recording, const FaultRun& ref, InjectedFault kind, const char* name,
                    double t_start_s, double t_end_s, double k, testing::Deviation* d) {
  InjectedFaultSpec spec;
  spec.kind = kind;
  spec.t_start_s = t_start_s;
  spec.t_end_s = t_end_s;
  spec.every_n = 2;
  spec.magnitude_sigma = k;
  FaultRun run = replayWithFaults(recording, name, spec);
  EXPECT_GT(run.tap->counters().injected, 10u);
  if (k >= 10.0) {
    EXPECT_EQ(run.tap->counters().accepted_injected, 0u);
  } else {
    EXPECT_LE(run.tap->counters().accepted_injected, run.tap->counters().injected / 10);
  }
  EXPECT_EQ(nonFiniteTicks(run), 0);
  *d = maxDeviation(run, ref);
  EXPECT_LT(d->position_m, 0.05);
  return run;
}

TEST(FaultVision, CameraFaultsAndFaultyVisionResults) {
  // GIVEN a rendered dive through both stages with 1 s of noise frames and 2 s without frames
  FaultRun base = replayWithFaults(dive(), "base", {}, kQuickStages);
  ASSERT_GE(base.summary.stage2_at_s, 0.0);
  ASSERT_LT(base.summary.stage2_at_s, 22.0);
  ASSERT_GE(base.summary.panel_fixed_at_s, 0.0);
  cameraFaults(base);

  // AND its recording (inputs as consumed, vision results included) replayed untouched: bit for bit
  const std::string recording = testing::tempPath("fault_base/replay.mcap");
  const FaultRun ref = replayWithFaults(recording, "ref");
  ASSERT_TRUE(ref.summary.reproduce);
  EXPECT_EQ(ref.summary.mismatches, 0u);
  ASSERT_GT(voAccepted(ref), 20u);
  const double s2 = base.summary.stage2_at_s + 1.0;
  const double panel = base.summary.panel_fixed_at_s + 1.0;
  const double end = kGarbageFrom_s - 1.0;

  // WHEN VO results carry 5-50 sigma outliers on every component (one result in two)
  for (double k : {5.0, 10.0, 20.0, 50.0}) {
    SCOPED_TRACE(testing::strf("vo outlier %.0f", k));
    // THEN none is accepted (5 sigma: almost none) and the estimate barely moves
    testing::Deviation d;
    const FaultRun run = outlierRun(recording, ref, InjectedFault::kVoOutlier, "vo_outlier", s2, end, k, &d);
    std::printf("[fault] vo outlier %2.0f sigma: %u outliers, false accepts %u, max deviation %.4f m %.3f deg\n", k,
                run.tap->counters().injected, run.tap->counters().accepted_injected, d.position_m,
                d.angle_rad * 180.0 / M_PI);
  }

  // WHEN marker poses carry 5-50 sigma outliers (each marker moved k position sigmas on every axis)
  for (double k : {5.0, 10.0, 20.0, 50.0}) {
    SCOPED_TRACE(testing::strf("marker outlier %.0f", k));
    testing::Deviation d;
    const FaultRun run = outlierRun(recording, ref, InjectedFault::kMarkerOutlier, "marker_outlier", panel, end, k, &d);
    std::printf("[fault] marker outlier %2.0f sigma: %u images with outliers, false accepts %u, max deviation %.4f m "
                "%.3f deg\n",
                k, run.tap->counters().injected, run.tap->counters().accepted_injected, d.position_m,
                d.angle_rad * 180.0 / M_PI);
  }

  // WHEN vision results arrive 50-300 ms later than usual (150 ms), or 400 ms (550 ms after capture,
  // beyond the 500 ms fusion window)
  for (double delay_ms : {50.0, 100.0, 200.0, 300.0, 400.0}) {
    SCOPED_TRACE(testing::strf("late %.0f", delay_ms));
    InjectedFaultSpec spec;
    spec.kind = InjectedFault::kVisionDelay;
    spec.t_start_s = s2;
    spec.t_end_s = end;
    spec.delay_ms = delay_ms;
    const FaultRun run = replayWithFaults(recording, "late", spec);
    EXPECT_EQ(nonFiniteTicks(run), 0);
    const testing::Deviation d = maxDeviation(run, ref);
    const std::uint32_t dropped = run.summary.inputs.dropped_late > ref.summary.inputs.dropped_late
                                      ? static_cast<std::uint32_t>(run.summary.inputs.dropped_late - ref.summary.inputs.dropped_late)
                                      : 0u;
    const bool beyond = 150.0 + delay_ms > 500.0;
    // THEN inside the window they are fused as in order (tiny differences: the output smoother saw the
    // corrections later); beyond it they are dropped and counted, and dead reckoning carries on
    if (!beyond) {
      EXPECT_LT(d.position_m, 0.01);
      EXPECT_GE(voAccepted(run) + 2, voAccepted(ref));
    } else {
      // every result beyond the window is a late drop (issue 21: they used to lose their clone silently)
      EXPECT_GT(dropped, 10u);
      EXPECT_GT(run.summary.vo.clones_late, 10u);
      EXPECT_LT(d.position_m, 0.05);
    }
    std::printf("[fault] vision results %3.0f ms late (%3.0f ms after capture): VO fused %u of %u in order, "
                "dropped late %u, no clone %u, clones late %u, max deviation from the in-order run %.4f m %.3f deg\n",
                delay_ms, 150.0 + delay_ms, voAccepted(run), voAccepted(ref), dropped, run.summary.vo.no_clone,
                run.summary.vo.clones_late,
                d.position_m, d.angle_rad * 180.0 / M_PI);
  }

  {
    // WHEN every other vision result arrives after the next one (pairs swapped)
    InjectedFaultSpec spec;
    spec.kind = InjectedFault::kVisionReorder;
    spec.t_start_s = s2;
    spec.t_end_s = end;
    spec.every_n = 2;
    const FaultRun run = replayWithFaults(recording, "reorder", spec);
    EXPECT_EQ(nonFiniteTicks(run), 0);
    const testing::Deviation d = maxDeviation(run, ref);
    EXPECT_LT(d.position_m, 0.02);
    std::printf("[fault] vision results reordered (%u pairs swapped): VO fused %u of %u in order, no clone %u, "
                "max deviation %.4f m %.3f deg\n",
                run.tap->counters().released, voAccepted(run), voAccepted(ref), run.summary.vo.no_clone, d.position_m,
                d.angle_rad * 180.0 / M_PI);
  }

  // WHEN VO covariances are NaN, Inf, negative, indefinite or huge
  const char* kValueNames[] = {"NaN", "Inf", "negative", "indefinite", "huge"};
  for (int value = 0; value < 5; ++value) {
    SCOPED_TRACE(kValueNames[value]);
    InjectedFaultSpec spec;
    spec.kind = InjectedFault::kBadCovariance;
    spec.target = CovarianceTarget::kVo;
    spec.value = static_cast<CovarianceValue>(value);
    spec.t_start_s = s2;
    spec.t_end_s = end;
    const FaultRun run = replayWithFaults(recording, "vo_cov", spec);
    // THEN no output is non-finite and none with a non-covariance is fused
    EXPECT_EQ(nonFiniteTicks(run), 0);
    EXPECT_GT(run.tap->counters().injected, 10u);
    if (spec.value != CovarianceValue::kHuge) {
      EXPECT_EQ(run.tap->counters().accepted_injected, 0u);
    }
    const testing::Deviation d = maxDeviation(run, ref);
    EXPECT_LT(d.position_m, 0.05);
    std::printf("[fault] vo covariance %s: %u results, accepted %u, non-finite outputs %d, max deviation %.4f m "
                "%.3f deg\n",
                kValueNames[value], run.tap->counters().injected, run.tap->counters().accepted_injected,
                nonFiniteTicks(run), d.position_m, d.angle_rad * 180.0 / M_PI);
  }
}

}  // namespace
}  // namespace deepnav
