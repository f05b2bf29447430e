// Issue 21 item 4, in the bare filter: a source whose clock jumped ahead (stamps beyond the delay window
// ahead of the loop's clock) is refused and flagged without feeding the lockout logic; a frozen IMU is
// refused so the state coasts instead of integrating a repeated message; a pair older than the window
// is known to be beyond it.
#include <gtest/gtest.h>

#include "base/so3.h"
#include "nav/ekf/ekf.h"

namespace deepnav {
namespace {

constexpr TimeUs kImuPeriodUs = 10'000;

// A resting IMU with a tiny deterministic dither (a working unit's noise never repeats every bit).
ImuSample noisyRestingImu(TimeUs t_us, int k) {
  ImuSample s;
  s.t_us = t_us;
  const double dither = 1e-6 * ((k * 7919) % 13 - 6);
  s.f_imu_mps2 = Eigen::Vector3d(dither, -dither, 9.80665 + dither);
  s.w_imu_radps = Eigen::Vector3d(dither, dither, -dither);
  return s;
}

DvlSample restingDvl(TimeUs t_us) {
  DvlSample d;
  d.t_us = t_us;
  d.valid = true;
  d.fom_mps = 0.01;
  d.cov_v_dvl_mps2 = Eigen::Matrix3d::Identity() * 1e-4;
  d.beam_valid_mask = 0xf;
  d.beam_range_m.fill(5.0);
  d.altitude_m = 4.3;
  return d;
}

// A filter aligned at rest after 1 s of IMU, the loop's clock at 1 s.
void startAtRest(Ekf* ekf, const EkfConfig& config, int* k) {
  ASSERT_TRUE(ekf->init(config, nullptr));
  ASSERT_TRUE(ekf->reset(0, EkfInitialState{}));
  for (*k = 1; *k <= 100; ++*k) ekf->setImu(noisyRestingImu(*k * kImuPeriodUs, *k));
  ekf->noteLoopTime(ekf->state().t_us);
  ASSERT_TRUE(ekf->aligned());
}

TEST(EkfClockFaults, DvlStampedBeyondTheWindowAheadOfTheLoopIsRefusedAndFlaggedWithoutALockout) {
  Ekf ekf;
  int k = 0;
  startAtRest(&ekf, EkfConfig{}, &k);
  const TimeUs now_us = ekf.state().t_us;
  // GIVEN a DVL sample on time, and one whose clock jumped 2 s ahead
  EXPECT_EQ(ekf.fuseDvl(restingDvl(now_us)).status, FuseStatus::kAccepted);
  const FuseResult ahead = ekf.fuseDvl(restingDvl(now_us + 2'000'000));
  // THEN the jumped one is refused as bad input, counted as a bad stamp, and raises the reject flag
  EXPECT_EQ(ahead.status, FuseStatus::kBadInput);
  EXPECT_EQ(ekf.health(kSrcDvl).counters.bad_stamps, 1u);
  EXPECT_TRUE(ekf.solution().faults & rejectBit(kSrcDvl));
  EXPECT_FALSE(ekf.health(kSrcDvl).last_rejected) << "a bad stamp must not count towards a gate lockout";
  // AND one within the window ahead (a sample the IMU has not reached yet) is queued as before
  EXPECT_EQ(ekf.fuseDvl(restingDvl(now_us + 400'000)).status, FuseStatus::kQueued);
  // AND the next sample fused on time clears the flag
  for (int i = 0; i < 50; ++i, ++k) ekf.setImu(noisyRestingImu(k * kImuPeriodUs, k));
  ekf.noteLoopTime(ekf.state().t_us);
  EXPECT_EQ(ekf.fuseDvl(restingDvl(ekf.state().t_us)).status, FuseStatus::kAccepted);
  EXPECT_FALSE(ekf.solution().faults & rejectBit(kSrcDvl));
  EXPECT_EQ(ekf.counters().gate_resets, 0u);
}

TEST(EkfClockFaults, WithoutTheLoopClockNothingIsJudgedByItsStamp) {
  // GIVEN a bare filter that never heard the loop's clock (unit tests, tools)
  Ekf ekf;
  ASSERT_TRUE(ekf.init(EkfConfig{}, nullptr));
  ASSERT_TRUE(ekf.reset(0, EkfInitialState{}));
  for (int k = 1; k <= 100; ++k) ekf.setImu(noisyRestingImu(k * kImuPeriodUs, k));
  // THEN a sample 2 s ahead of the IMU is queued as before
  EXPECT_EQ(ekf.fuseDvl(restingDvl(3'000'000)).status, FuseStatus::kQueued);
  EXPECT_EQ(ekf.health(kSrcDvl).counters.bad_stamps, 0u);
}

TEST(EkfClockFaults, FrozenImuIsRefusedTheStateCoastsAndResumesAfterIt) {
  EkfConfig config;
  config.imu_stuck_after_samples = 10;
  Ekf ekf;
  int k = 0;
  startAtRest(&ekf, config, &k);
  // GIVEN the IMU repeats one message (bit for bit, fresh stamps) for 1 s
  const ImuSample frozen = noisyRestingImu(0, 12345);
  const TimeUs t_frozen_start = ekf.state().t_us;
  for (int i = 0; i < 100; ++i, ++k) {
    ImuSample s = frozen;
    s.t_us = k * kImuPeriodUs;
    ekf.setImu(s);
  }
  // THEN the first 9 are integrated and the rest refused as frozen: the state stops, the IMU goes stale
  EXPECT_EQ(ekf.health(kSrcImu).counters.frozen, 91u);
  EXPECT_EQ(ekf.state().t_us, t_frozen_start + 9 * kImuPeriodUs);
  const NavSolution during = ekf.solution(k * kImuPeriodUs);
  EXPECT_TRUE(during.faults & staleBit(kSrcImu));
  EXPECT_TRUE(during.faults & rejectBit(kSrcImu));
  EXPECT_TRUE(during.p_robot_in_odom_m.allFinite());
  // AND when the IMU works again the state resumes from the next sample
  for (int i = 0; i < 20; ++i, ++k) ekf.setImu(noisyRestingImu(k * kImuPeriodUs, k));
  EXPECT_EQ(ekf.state().t_us, (k - 1) * kImuPeriodUs);
  const NavSolution after = ekf.solution(ekf.state().t_us);
  EXPECT_FALSE(after.faults & staleBit(kSrcImu));
  EXPECT_LT(after.p_robot_in_odom_m.norm(), 0.05);
}

TEST(EkfClockFaults, ImuStuckCheckIsOffInTheBareFilter) {
  // GIVEN the bare filter's default (0: unchecked), a noiseless resting IMU is integrated as before
  Ekf ekf;
  ASSERT_TRUE(ekf.init(EkfConfig{}, nullptr));
  ASSERT_TRUE(ekf.reset(0, EkfInitialState{}));
  ImuSample s;
  s.f_imu_mps2 = Eigen::Vector3d(0.0, 0.0, 9.80665);
  for (int k = 1; k <= 200; ++k) {
    s.t_us = k * kImuPeriodUs;
    ekf.setImu(s);
  }
  EXPECT_EQ(ekf.state().t_us, 200 * kImuPeriodUs);
  EXPECT_EQ(ekf.health(kSrcImu).counters.frozen, 0u);
  // AND a bad count is refused naming the key
  EkfConfig bad;
  bad.imu_stuck_after_samples = 1;
  std::string error;
  EXPECT_FALSE(Ekf().init(bad, &error));
  EXPECT_NE(error.find("imu_stuck_after_samples"), std::string::npos);
}

TEST(EkfClockFaults, APairOlderThanTheWindowIsBeyondIt) {
  Ekf ekf;
  int k = 0;
  startAtRest(&ekf, EkfConfig{}, &k);
  const TimeUs now_us = ekf.state().t_us;
  EXPECT_FALSE(ekf.beyondWindow(now_us - 100'000));
  EXPECT_TRUE(ekf.beyondWindow(now_us - 600'000));
  EXPECT_EQ(ekf.clonePose(now_us - 600'000, 1).status, FuseStatus::kDroppedLate);
}

}  // namespace
}  // namespace deepnav
