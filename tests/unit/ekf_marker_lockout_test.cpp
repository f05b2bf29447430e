// A marker-pose gate lockout (nav/ekf/gate_reset.h): the filter's position ends up off the markers by
// more than its gate while it is confident (at sea: an occlusion of the markers, plane VO results pulling
// the position 10 cm off meanwhile); without a reset every later marker pose is refused for the rest of
// the dive. With it, marker poses that agree with each other and have all been refused for
// gate_reset_after_us get the position and attitude variances raised to their initial sigmas, and the
// next pose is fused.
#include <cmath>
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/ekf.h"
#include "tests/support/resting_imu.h"

namespace deepnav {
namespace {

constexpr TimeUs kImuPeriodUs = 10'000;  // 100 Hz
constexpr double kMarkerSigmaM = 0.01;
constexpr double kMarkerSigmaRad = 0.2 * std::numbers::pi / 180.0;

// One IMU sample of a robot at rest (which propagates the filter and fuses what was queued), then the
// marker poses captured at or after from_s among the fusions it reports, counted as fused or refused.
void stepAtRest(TimeUs t_us, double from_s, Ekf* ekf, int* fused, int* refused) {
  testing::feedRestingImu(t_us, ekf);
  for (int i = 0; i < ekf->diagnostics().size(); ++i) {
    const FusionDiagnostic& d = ekf->diagnostics().at(i);
    if (d.source != kSrcMarkers || usToS(d.t_us) < from_s) continue;
    ++*(d.reason == FusionReason::kFused ? fused : refused);
  }
  ekf->clearDiagnostics();
}

struct Outcome {
  int markers_fused_after_offset = 0;
  int markers_refused_after_offset = 0;
  double y_at_end_m = 0.0;
  double y_sigma_at_end_m = 0.0;
  std::uint32_t gate_resets = 0;
};

// A robot at rest at the origin: IMU 100 Hz, depth and zero DVL 10 Hz, marker poses at 10 Hz. From
// offset_s on, the marker poses say y = offset_m: to the filter, which has held y = 0 with millimetre
// confidence, the same as its own position having been pulled off by that much.
Outcome run(TimeUs gate_reset_after_us, double offset_s, double offset_m, double duration_s) {
  EkfConfig config;
  config.gate_reset_after_us = gate_reset_after_us;
  Ekf ekf;
  EXPECT_TRUE(ekf.init(config, nullptr));
  EXPECT_TRUE(ekf.reset(0, EkfInitialState{}));
  std::mt19937 rng(11);
  std::normal_distribution<double> noise(0.0, 1.0);
  Outcome out;
  const int steps = static_cast<int>(duration_s * 100.0);
  for (int k = 1; k <= steps; ++k) {
    const TimeUs t_us = k * kImuPeriodUs;
    const TimeUs t_meas_us = t_us - kImuPeriodUs / 2;
    const double t_s = usToS(t_meas_us);
    if (k % 10 == 0) {
      DepthSample d;
      d.t_us = t_meas_us;
      ekf.fuseDepth(d);
      DvlSample v;
      v.t_us = t_meas_us + 1;
      v.valid = true;
      ekf.fuseDvl(v);
      PoseMeasurement p;
      p.t_us = t_meas_us + 2;
      p.p_robot_in_odom_m = kMarkerSigmaM * Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      if (t_s >= offset_s) p.p_robot_in_odom_m.y() += offset_m;
      p.q_odom_robot = quatFromRollPitchYaw(kMarkerSigmaRad * noise(rng), kMarkerSigmaRad * noise(rng),
                                            kMarkerSigmaRad * noise(rng));
      p.cov_pose.setZero();
      p.cov_pose.diagonal() << Eigen::Vector3d::Constant(kMarkerSigmaM * kMarkerSigmaM),
          Eigen::Vector3d::Constant(kMarkerSigmaRad * kMarkerSigmaRad);
      ekf.fusePose(p);
    }
    stepAtRest(t_us, offset_s, &ekf, &out.markers_fused_after_offset, &out.markers_refused_after_offset);
  }
  out.y_at_end_m = ekf.state().x.p_robot_in_odom_m.y();
  out.y_sigma_at_end_m = std::sqrt(ekf.state().P(es::kP + 1, es::kP + 1));
  out.gate_resets = ekf.counters().gate_resets;
  return out;
}

TEST(EkfMarkerLockout, MarkersThatAgreeButAreRefusedForTwoSecondsGetTheFilterBack) {
  // GIVEN 30 s of marker poses at the origin, then 30 s of poses 0.25 m off in y (25 sigma of the marker
  // noise, far outside the gate of a filter that has converged on them, within the 3 sigma of the
  // initial position sigma that the reset restores)
  const Outcome with_reset = run(2'000'000, 30.0, 0.25, 60.0);
  const Outcome without = run(0, 30.0, 0.25, 60.0);
  std::printf("markers after the offset: with the reset %d fused, %d refused, end y %.4f m (sigma %.4f), %u resets; "
              "without %d fused, %d refused, end y %.4f m\n",
              with_reset.markers_fused_after_offset, with_reset.markers_refused_after_offset, with_reset.y_at_end_m,
              with_reset.y_sigma_at_end_m, with_reset.gate_resets, without.markers_fused_after_offset,
              without.markers_refused_after_offset, without.y_at_end_m);
  // THEN without the reset the filter refuses them until its own position variance, grown on the DVL
  // alone, opens the gate: more than 10 s (at sea, where the VO holds the position variance down as
  // well, that lasted the rest of the dive)
  EXPECT_EQ(without.gate_resets, 0u);
  EXPECT_GT(without.markers_refused_after_offset, 100);
  // AND with it the poses are refused for the 2 s the reset waits (20 at 10 Hz, plus the samples in
  // flight), the filter is reset once and fuses the rest, and it ends on the markers
  EXPECT_EQ(with_reset.gate_resets, 1u);
  EXPECT_LE(with_reset.markers_refused_after_offset, 25);
  EXPECT_GT(with_reset.markers_fused_after_offset, 270);
  EXPECT_NEAR(with_reset.y_at_end_m, 0.25, 0.01);
  EXPECT_LT(with_reset.y_sigma_at_end_m, 0.01);
}

TEST(EkfMarkerLockout, ASingleOutlierIsRefusedWithoutAReset) {
  // GIVEN marker poses at the origin with one 0.5 m outlier (a misdetection) every 3 s
  EkfConfig config;
  Ekf ekf;
  ASSERT_TRUE(ekf.init(config, nullptr));
  ASSERT_TRUE(ekf.reset(0, EkfInitialState{}));
  int fused = 0, refused = 0;
  for (int k = 1; k <= 6000; ++k) {
    const TimeUs t_us = k * kImuPeriodUs;
    if (k % 10 == 0) {
      DvlSample v;
      v.t_us = t_us - 5000;
      v.valid = true;
      ekf.fuseDvl(v);
      PoseMeasurement p;
      p.t_us = t_us - 4000;
      if (k % 300 == 0) p.p_robot_in_odom_m.x() = 0.5;
      p.cov_pose = Eigen::Matrix<double, 6, 6>::Identity() * 1e-4;
      ekf.fusePose(p);
    }
    stepAtRest(t_us, 0.0, &ekf, &fused, &refused);
  }
  // THEN each outlier is refused, nothing is reset and the estimate stays at the origin
  EXPECT_GE(refused, 19);
  EXPECT_EQ(ekf.counters().gate_resets, 0u);
  EXPECT_LT(ekf.state().x.p_robot_in_odom_m.norm(), 0.01);
}

}  // namespace
}  // namespace deepnav
