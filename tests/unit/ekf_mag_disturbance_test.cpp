// The compass near steel (nav/ekf/mag_disturbance.h): a heading offset that ramps to several degrees while
// absolute poses hold the yaw is detected, the compass de-weighted then refused, the yaw not dragged, and
// fusion restored when the offset goes; a clean compass is never flagged. Also the per-fusion diagnostics
// (fusion_diagnostic.h) of accepted, gated, refused and door-refused measurements, and their CDR round trip.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "drivers/cdr/ros2msg_definitions.h"
#include "drivers/recording/fusion_codec.h"
#include "drivers/recording/topics.h"
#include "nav/ekf/ekf.h"
#include "nav/ekf/mag_disturbance.h"
#include "tests/support/resting_imu.h"

namespace deepnav {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr double kYawTrue = 0.4;           // rad, ENU
constexpr double kCompassSigma = 0.0052;   // rad, the sea board's figure
constexpr TimeUs kImuPeriodUs = 10'000;    // 100 Hz

// Compass offset (rad) of the disturbance: 0 until on_s, a ramp to peak over ramp_s, held until off_s,
// back to 0 over ramp_s (a vehicle approaching the panel, keeping station there, leaving).
struct Disturbance {
  double on_s = 1e9, off_s = 1e9, ramp_s = 10.0, peak_rad = 0.0;
  double at(double t_s) const {
    if (t_s < on_s) return 0.0;
    if (t_s < on_s + ramp_s) return peak_rad * (t_s - on_s) / ramp_s;
    if (t_s < off_s) return peak_rad;
    if (t_s < off_s + ramp_s) return peak_rad * (1.0 - (t_s - off_s) / ramp_s);
    return 0.0;
  }
};

struct Trace {
  std::vector<double> t_s, yaw_err_rad;
  std::vector<MagState> state;
  std::vector<FusionDiagnostic> compass;  // diagnostics of the compass samples
  std::vector<FusionDiagnostic> markers;
};

EkfConfig magConfig(bool enabled) {
  EkfConfig c;
  c.mag_disturbance_enabled = enabled;
  c.heading_sigma_rad = kCompassSigma;
  c.gyro_arw_radps_rthz = 4.36e-5;  // tactical grade, as the sea board
  c.gyro_bias_rw_radps2_rthz = 3.25e-7;
  return c;
}

// A robot at rest at yaw kYawTrue: IMU 100 Hz, compass 10 Hz (white noise + the disturbance), depth and
// zero DVL 10 Hz, marker poses (yaw sigma 0.2 deg) at 2 Hz when markers_hz > 0.
Trace run(const EkfConfig& config, const Disturbance& dist, double duration_s, double markers_hz,
          Ekf* ekf, unsigned seed = 7) {
  EXPECT_TRUE(ekf->init(config, nullptr));
  EkfInitialState init;
  init.x.q_odom_robot = quatFromRollPitchYaw(0.0, 0.0, kYawTrue);
  EXPECT_TRUE(ekf->reset(0, init));
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  Trace tr;
  const int steps = static_cast<int>(duration_s * 100.0);
  const int marker_every = markers_hz > 0.0 ? static_cast<int>(100.0 / markers_hz) : 0;
  for (int k = 1; k <= steps; ++k) {
    const TimeUs t_us = k * kImuPeriodUs;
    const TimeUs t_meas_us = t_us - kImuPeriodUs / 2;  // between two IMU samples: queued, fused in order
    const double t_s = usToS(t_meas_us);
    if (k % 10 == 0) {
      HeadingSample h;
      h.t_us = t_meas_us;
      const double yaw_meas = kYawTrue + dist.at(t_s) + kCompassSigma * noise(rng);
      h.heading_rad = std::numbers::pi / 2.0 - yaw_meas;
      ekf->fuseHeading(h);
      DepthSample d;
      d.t_us = t_meas_us + 1;
      d.depth_m = 0.0;
      ekf->fuseDepth(d);
      DvlSample v;
      v.t_us = t_meas_us + 2;
      v.valid = true;
      ekf->fuseDvl(v);
    }
    if (marker_every > 0 && k % marker_every == 0) {
      PoseMeasurement p;
      p.t_us = t_meas_us + 3;
      const double yaw_noise = 0.2 * kDeg * noise(rng);
      p.q_odom_robot = quatFromRollPitchYaw(0.0, 0.0, kYawTrue + yaw_noise);
      p.cov_pose.setZero();
      p.cov_pose.diagonal() << 1e-4, 1e-4, 1e-4, std::pow(0.2 * kDeg, 2), std::pow(0.2 * kDeg, 2),
          std::pow(0.2 * kDeg, 2);
      ekf->fusePose(p);
    }
    testing::feedRestingImu(t_us, ekf);
    for (int i = 0; i < ekf->diagnostics().size(); ++i) {
      const FusionDiagnostic& d = ekf->diagnostics().at(i);
      if (d.source == kSrcHeading) tr.compass.push_back(d);
      if (d.source == kSrcMarkers) tr.markers.push_back(d);
    }
    ekf->clearDiagnostics();
    const Eigen::Matrix3d R = ekf->state().x.q_odom_robot.toRotationMatrix();
    tr.t_s.push_back(usToS(t_us));
    tr.yaw_err_rad.push_back(wrapPi(std::atan2(R(1, 0), R(0, 0)) - kYawTrue));
    tr.state.push_back(ekf->magDisturbance().state());
  }
  return tr;
}

double firstTimeIn(const Trace& tr, MagState s, double after_s) {
  for (std::size_t i = 0; i < tr.t_s.size(); ++i) {
    if (tr.t_s[i] >= after_s && tr.state[i] == s) return tr.t_s[i];
  }
  return 1e9;
}

double maxAbsYawError(const Trace& tr, double from_s, double to_s) {
  double m = 0.0;
  for (std::size_t i = 0; i < tr.t_s.size(); ++i) {
    if (tr.t_s[i] >= from_s && tr.t_s[i] < to_s) m = std::max(m, std::abs(tr.yaw_err_rad[i]));
  }
  return m;
}

TEST(EkfMagDisturbance, EnteringIsDetectedCompassRefusedYawHeldAndLeavingRestoresFusion) {
  // GIVEN markers holding the yaw and a compass offset ramping from 0 to 5 deg over 10 s from t = 60 s,
  // held until 120 s, gone by 130 s (the vehicle keeps station by the panel, then leaves)
  Disturbance dist;
  dist.on_s = 60.0;
  dist.off_s = 120.0;
  dist.peak_rad = 5.0 * kDeg;
  Ekf ekf;
  const Trace tr = run(magConfig(true), dist, 180.0, 2.0, &ekf);
  const MagDisturbanceCounters& c = ekf.magDisturbance().counters();
  // THEN the compass is de-weighted before the offset reaches 1.5 deg (t = 63 s) and refused before 3 deg
  // (66 s): the low-pass (tau 3 s) lags a ramp by about tau
  const double t_suspect = firstTimeIn(tr, MagState::kSuspect, 0.0);
  const double t_disturbed = firstTimeIn(tr, MagState::kDisturbed, 0.0);
  RecordProperty("t_suspect_s", std::to_string(t_suspect));
  RecordProperty("t_disturbed_s", std::to_string(t_disturbed));
  EXPECT_GT(t_suspect, 60.0);
  EXPECT_LT(t_suspect, 63.0);
  EXPECT_LT(t_disturbed, 66.0);
  EXPECT_EQ(c.disturbed_entries, 1u);
  // AND the yaw is not dragged by more than 0.4 deg (undetected, the compass drags it past 1 deg: the test
  // below; the drag happens before the refusal, while the compass at 10 Hz outweighs the markers at 2 Hz)
  EXPECT_LT(maxAbsYawError(tr, 0.0, 180.0), 0.4 * kDeg);
  // AND while disturbed the compass is refused, the status says so, and nothing locks out or resets
  EXPECT_GT(c.refused, 450u);  // 10 Hz over most of [66, 130] s
  EXPECT_EQ(ekf.counters().gate_resets, 0u);
  // AND after the disturbance is gone (130 s) the compass is clean again once the low-passed innovation
  // has decayed from the ramp's lag (about 5 sigma) below exit (0.5): tau ln 10 = 6.9 s, plus the 3 s hold,
  // within 2 s
  const double t_clean = firstTimeIn(tr, MagState::kClean, 125.0);
  RecordProperty("t_clean_s", std::to_string(t_clean));
  RecordProperty("max_yaw_error_deg", std::to_string(maxAbsYawError(tr, 0.0, 180.0) / kDeg));
  EXPECT_LT(t_clean, 130.0 + 6.9 + 3.0 + 2.0);
  EXPECT_EQ(tr.state.back(), MagState::kClean);
  EXPECT_GE(c.recoveries, 1u);
  EXPECT_FALSE(ekf.solution().status & kStatusMagDisturbed);
  // AND the diagnostics tell the same story: refused compass samples carry their innovation (about the
  // offset) and the reason; the last ones are fused again
  int refused = 0;
  for (const FusionDiagnostic& d : tr.compass) {
    if (d.reason != FusionReason::kMagDisturbance) continue;
    ++refused;
    EXPECT_EQ(d.dim, 1);
    EXPECT_GT(d.innovation_variance[0], 0.0);
    EXPECT_EQ(d.mag_state, static_cast<std::uint8_t>(MagState::kDisturbed));
  }
  EXPECT_EQ(static_cast<std::uint32_t>(refused), c.refused);
  EXPECT_EQ(tr.compass.back().reason, FusionReason::kFused);
  EXPECT_EQ(ekf.health(kSrcHeading).counters.accepted + c.refused + ekf.health(kSrcHeading).counters.rejected,
            tr.compass.size());
}

TEST(EkfMagDisturbance, StatusBitWhileDisturbed) {
  // GIVEN a 5 deg offset that stays
  Disturbance dist;
  dist.on_s = 20.0;
  dist.peak_rad = 5.0 * kDeg;
  Ekf ekf;
  const Trace tr = run(magConfig(true), dist, 60.0, 2.0, &ekf);
  // THEN the compass stays refused and the solution flags it, without the compass's reject bit
  EXPECT_EQ(tr.state.back(), MagState::kDisturbed);
  const NavSolution s = ekf.solution();
  EXPECT_TRUE(s.status & kStatusMagDisturbed);
  EXPECT_FALSE(s.faults & rejectBit(kSrcHeading));
  EXPECT_FALSE(s.faults & staleBit(kSrcHeading));
}

TEST(EkfMagDisturbance, CleanCompassIsNeverFlagged) {
  // GIVEN a clean compass over 20 min with markers holding the yaw (the only case where it is judged)
  for (const double markers_hz : {2.0, 0.5}) {
    for (const unsigned seed : {1u, 2u}) {
      Ekf ekf;
      const Trace tr = run(magConfig(true), Disturbance{}, 1200.0, markers_hz, &ekf, seed);
      // THEN the detector never leaves clean and every compass sample is judged and fused
      const MagDisturbanceCounters& c = ekf.magDisturbance().counters();
      EXPECT_EQ(c.suspect_entries + c.disturbed_entries, 0u) << "markers " << markers_hz << " seed " << seed;
      EXPECT_EQ(c.samples, tr.compass.size());
      EXPECT_EQ(c.deweighted + c.refused, 0u);
    }
  }
}

TEST(EkfMagDisturbance, WithoutMarkersTheCompassIsKept) {
  // GIVEN the same disturbance and no marker pose: the compass is the only heading reference
  Disturbance dist;
  dist.on_s = 60.0;
  dist.off_s = 120.0;
  dist.peak_rad = 5.0 * kDeg;
  Ekf ekf;
  run(magConfig(true), dist, 130.0, 0.0, &ekf);
  // THEN every sample is judged but none is de-weighted or refused
  const MagDisturbanceCounters& c = ekf.magDisturbance().counters();
  EXPECT_EQ(c.samples, 1300u);
  EXPECT_EQ(c.deweighted + c.refused + c.suspect_entries + c.disturbed_entries, 0u);
}

TEST(EkfMagDisturbance, OffByDefaultTheCompassDragsTheYawAsBefore) {
  // GIVEN the same disturbance with the detector off (every existing board)
  Disturbance dist;
  dist.on_s = 60.0;
  dist.off_s = 120.0;
  dist.peak_rad = 5.0 * kDeg;
  Ekf off;
  const Trace tr = run(magConfig(false), dist, 130.0, 2.0, &off);
  // THEN nothing is judged, no sample refused, and the yaw follows the compass well past the detector's bound
  EXPECT_EQ(off.magDisturbance().counters().samples, 0u);
  EXPECT_EQ(off.magDisturbance().state(), MagState::kClean);
  EXPECT_GT(maxAbsYawError(tr, 60.0, 130.0), 1.0 * kDeg);
}

TEST(EkfMagDisturbance, DetectorHysteresis) {
  // GIVEN the detector alone, the yaw held (H P H^T << R), R = 1
  MagDisturbanceParams p;
  p.enabled = true;
  MagDisturbanceDetector det;
  det.configure(p);
  TimeUs t = 0;
  auto feed = [&](double innovation, double seconds) {
    MagAction a = MagAction::kFuse;
    for (int i = 0; i < static_cast<int>(seconds * 10); ++i) {
      a = det.update(t += 100'000, innovation, 0.01, 1.0, true);
    }
    return a;
  };
  // WHEN the innovation sits at 1.5 sigma: de-weighted, not refused
  EXPECT_EQ(feed(1.5, 20.0), MagAction::kDeweight);
  EXPECT_EQ(det.state(), MagState::kSuspect);
  // AND at 3 sigma: refused, but only de-weighted while no marker pose holds the heading
  EXPECT_EQ(feed(3.0, 20.0), MagAction::kRefuse);
  EXPECT_EQ(det.update(t += 100'000, 3.0, 0.01, 1.0, false), MagAction::kDeweight);
  EXPECT_EQ(det.state(), MagState::kDisturbed);
  // AND back at 0.7 sigma (between exit and suspect): still refused (hysteresis)
  EXPECT_EQ(feed(0.7, 30.0), MagAction::kRefuse);
  // AND at 0 sigma: clean again after the hold
  EXPECT_EQ(feed(0.0, 30.0), MagAction::kFuse);
  EXPECT_EQ(det.state(), MagState::kClean);
  EXPECT_EQ(det.counters().recoveries, 1u);
  // AND with the yaw not held (H P H^T > R) a large offset is the state's error, not the compass's
  det.restart();
  for (int i = 0; i < 300; ++i) det.update(t += 100'000, 3.0, 10.0, 1.0, true);
  EXPECT_EQ(det.state(), MagState::kClean);
  // AND without an absolute pose fused recently the compass, the only heading reference, is never refused
  for (int i = 0; i < 300; ++i) det.update(t += 100'000, 3.0, 0.01, 1.0, false);
  EXPECT_EQ(det.state(), MagState::kClean);
}

TEST(FusionDiagnostics, GatedAndDoorRefusedMeasurementsAreReported) {
  // GIVEN an aligned filter at rest
  Ekf ekf;
  const Trace tr = run(magConfig(false), Disturbance{}, 2.0, 2.0, &ekf);
  ASSERT_FALSE(tr.markers.empty());
  EXPECT_EQ(tr.markers.back().reason, FusionReason::kFused);
  EXPECT_EQ(tr.markers.back().dim, 6);
  EXPECT_GT(tr.markers.back().innovation_variance[5], 0.0);
  // WHEN a depth 1 m off (gate), a NaN compass (bad input) and a depth 2 s late arrive
  DepthSample d;
  d.t_us = ekf.state().t_us + 5'000;
  d.depth_m = 1.0;
  ekf.fuseDepth(d);
  HeadingSample h;
  h.t_us = ekf.state().t_us + 6'000;
  h.heading_rad = std::numeric_limits<double>::quiet_NaN();
  ekf.fuseHeading(h);
  d.t_us = ekf.state().t_us - 2'000'000;
  d.depth_m = 0.0;
  ekf.fuseDepth(d);
  testing::feedRestingImu(ekf.state().t_us + kImuPeriodUs, &ekf);
  // THEN each is reported with its reason; the gated one with its innovation and test ratio
  std::vector<FusionDiagnostic> got;
  for (int i = 0; i < ekf.diagnostics().size(); ++i) got.push_back(ekf.diagnostics().at(i));
  ASSERT_EQ(got.size(), 3u);
  EXPECT_EQ(got[0].source, kSrcHeading);
  EXPECT_EQ(got[0].reason, FusionReason::kBadInput);
  EXPECT_EQ(got[1].source, kSrcDepth);
  EXPECT_EQ(got[1].reason, FusionReason::kLate);
  EXPECT_EQ(got[2].source, kSrcDepth);
  EXPECT_EQ(got[2].reason, FusionReason::kGate);
  EXPECT_EQ(got[2].dim, 1);
  EXPECT_NEAR(std::abs(got[2].innovation[0]), 1.0, 0.05);
  EXPECT_GT(got[2].test_ratio, 1.0);
}

TEST(FusionDiagnostics, CdrRoundTripAndSchema) {
  // GIVEN a refused compass sample and a fused 6-dof pose
  FusionDiagnostic a;
  a.t_us = 123'456'789;
  a.source = kSrcHeading;
  a.reason = FusionReason::kMagDisturbance;
  a.dim = 1;
  a.innovation[0] = 0.08;
  a.innovation_variance[0] = 2.7e-5;
  a.test_ratio = 26.3;
  a.mag_state = 2;
  FusionDiagnostic b;
  b.t_us = 5;
  b.source = kSrcMarkers;
  b.reason = FusionReason::kFused;
  b.dim = 6;
  for (int i = 0; i < 6; ++i) {
    b.innovation[static_cast<std::size_t>(i)] = 0.01 * (i - 2);
    b.innovation_variance[static_cast<std::size_t>(i)] = 1e-4 * (i + 1);
  }
  b.test_ratio = 0.2;
  for (const FusionDiagnostic& d : {a, b}) {
    // WHEN encoded and decoded
    std::vector<std::uint8_t> buf(512);
    const std::size_t n = encodeFusion(d, buf.data(), buf.size());
    ASSERT_GT(n, 0u);
    FusionDiagnostic back;
    ASSERT_TRUE(decodeFusion(buf.data(), n, &back));
    // THEN every field comes back bit for bit, and a truncated message is refused
    EXPECT_EQ(back.t_us, d.t_us);
    EXPECT_EQ(back.source, d.source);
    EXPECT_EQ(back.reason, d.reason);
    EXPECT_EQ(back.dim, d.dim);
    EXPECT_EQ(back.mag_state, d.mag_state);
    EXPECT_EQ(back.test_ratio, d.test_ratio);
    for (int i = 0; i < d.dim; ++i) {
      EXPECT_EQ(back.innovation[static_cast<std::size_t>(i)], d.innovation[static_cast<std::size_t>(i)]);
      EXPECT_EQ(back.innovation_variance[static_cast<std::size_t>(i)],
                d.innovation_variance[static_cast<std::size_t>(i)]);
    }
    EXPECT_FALSE(decodeFusion(buf.data(), n - 9, &back));
    EXPECT_EQ(encodeFusion(d, buf.data(), 16), 0u);
  }
  // AND the topic is registered with a schema that names every field
  EXPECT_EQ(topicByName("/nav/fusion"), Topic::kFusion);
  const std::string_view schema = topicSchema(Topic::kFusion);
  for (const char* field : {"source_name", "reason_name", "float64[] innovation", "innovation_variance",
                            "test_ratio", "mag_state", "std_msgs/Header header"}) {
    EXPECT_NE(schema.find(field), std::string_view::npos) << field;
  }
}

}  // namespace
}  // namespace deepnav
