// Xsens Xbus framing and MTData2 decoding.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/parsers/frame_plausibility.h"
#include "drivers/parsers/xbus_framer.h"
#include "drivers/parsers/xsens_mtdata2.h"
#include "tests/support/sensor_frames.h"

namespace deepnav {
namespace {

TEST(XsensParser, MtData2ThroughTheFramer) {
  const double roll = 0.1, pitch = -0.2;  // ZYX with yaw 0: q = qy(pitch) * qx(roll)
  const float q[4] = {float(std::cos(roll / 2) * std::cos(pitch / 2)), float(std::sin(roll / 2) * std::cos(pitch / 2)),
                      float(std::cos(roll / 2) * std::sin(pitch / 2)), float(-std::sin(roll / 2) * std::sin(pitch / 2))};
  const float acc[3] = {0.1f, 0.2f, 9.81f}, gyr[3] = {0.01f, -0.02f, 0.03f};
  std::vector<uint8_t> stream = {0x00, 0xFA, 0x13};  // noise, including a false preamble
  for (uint16_t c = 0; c < 3; ++c) {
    const auto m = test::buildMtData2(c, q, acc, gyr);
    stream.insert(stream.end(), m.begin(), m.end());
  }
  XbusFramer framer;
  ASSERT_TRUE(framer.init(1024));
  framer.push(stream.data(), stream.size());
  int messages = 0, bad = 0;
  RawFrame f;
  FrameError e;
  for (FrameStatus st; (st = framer.next(&f, &e)) != FrameStatus::kNeedMore;) {
    if (st == FrameStatus::kBad) {
      ++bad;
      continue;
    }
    XbusMessage msg;
    ASSERT_TRUE(splitXbusFrame(f.data, f.size, &msg));
    ASSERT_EQ(msg.message_id, kXbusMtData2);
    XsensMtData2 d;
    const char* why = "";
    ASSERT_TRUE(decodeXsensMtData2(msg.payload, msg.payload_size, &d, &why)) << why;
    EXPECT_EQ(d.packet_counter, messages);
    ImuSample imu;
    ASSERT_TRUE(imuSampleFromXsens(d, 5, &imu));
    EXPECT_NEAR(imu.f_imu_mps2.z(), 9.81, 1e-6);
    EXPECT_NEAR(imu.w_imu_radps.y(), -0.02, 1e-7);
    EXPECT_TRUE(imu.has_orientation);
    AttitudeSample att;
    ASSERT_TRUE(attitudeSampleFromXsens(d, 5, &att));
    EXPECT_NEAR(att.roll_rad, roll, 1e-6);
    EXPECT_NEAR(att.pitch_rad, pitch, 1e-6);
    ++messages;
  }
  EXPECT_EQ(messages, 3);
  EXPECT_GE(bad, 1);
}

TEST(XsensParser, MalformedPacketsAreRejected) {
  XsensMtData2 d;
  const char* why = "";
  const uint8_t runs_past[] = {0x40, 0x20, 12, 0, 0};
  EXPECT_FALSE(decodeXsensMtData2(runs_past, sizeof runs_past, &d, &why));
  const uint8_t wrong_size[] = {0x40, 0x20, 4, 0, 0, 0, 0};  // acceleration needs 12 bytes as float32
  EXPECT_FALSE(decodeXsensMtData2(wrong_size, sizeof wrong_size, &d, &why));
  const uint8_t fp1632[] = {0x80, 0x22, 18, 0, 0, 0, 0, 0, 1, 0x80, 0, 0, 0, 0xFF, 0xFF, 0, 0, 0, 0, 0, 0};
  ASSERT_TRUE(decodeXsensMtData2(fp1632, sizeof fp1632, &d, &why)) << why;
  EXPECT_NEAR(d.rate_of_turn_radps[0], 1.0, 1e-12);
  EXPECT_NEAR(d.rate_of_turn_radps[1], -0.5, 1e-12);
  const uint8_t unknown[] = {0x70, 0x10, 2, 1, 2};  // unknown XDI: skipped
  EXPECT_TRUE(decodeXsensMtData2(unknown, sizeof unknown, &d, &why));
  EXPECT_EQ(d.num_packets, 1);
}

}  // namespace
}  // namespace deepnav

namespace deepnav {
namespace {

// The plausibility of one MTData2 message after a run of good ones (frame_plausibility.h).
FramePlausibility::Verdict verdictAfterGoodRun(const float q_last[4], const float acc_last[3], const float gyr_last[3]) {
  const float q[4] = {1.0f, 0.0f, 0.0f, 0.0f};
  const float acc[3] = {0.1f, 0.2f, 9.81f}, gyr[3] = {0.01f, -0.02f, 0.03f};
  FramePlausibility plausible;
  FramePlausibility::Verdict v = FramePlausibility::Verdict::kAccepted;
  for (uint16_t c = 0; c < 6; ++c) {
    const bool last = c == 5;
    const auto bytes = test::buildMtData2(c, last ? q_last : q, last ? acc_last : acc, last ? gyr_last : gyr);
    XbusMessage m;
    XsensMtData2 d;
    const char* why = "";
    EXPECT_TRUE(splitXbusFrame(bytes.data(), bytes.size(), &m));
    EXPECT_TRUE(decodeXsensMtData2(m.payload, m.payload_size, &d, &why)) << why;
    v = plausible.checkXsens(m, d);
    if (!last) {
      EXPECT_EQ(v, FramePlausibility::Verdict::kAccepted);
    }
  }
  return v;
}

TEST(XsensPlausibility, DamagedValuesWhoseSumHoldsAreRefusedAsSteps) {
  // GIVEN good messages (at rest, level), then one whose sum holds but a float lost or gained a power of
  // two (the damage fault_bit_errors_test found passing at a bit error rate of 1e-3)
  const float q[4] = {1.0f, 0.0f, 0.0f, 0.0f};
  const float acc[3] = {0.1f, 0.2f, 9.81f}, gyr[3] = {0.01f, -0.02f, 0.03f};
  const float acc_doubled[3] = {0.1f, 0.2f, 19.62f}, acc_quartered[3] = {0.1f, 0.2f, 2.45f};
  const float gyr_spike[3] = {0.01f, -0.02f, 0.33f};
  const double half = 0.5 * 3.0 * M_PI / 180.0;  // a 3 deg roll step in one frame
  const float q_rolled[4] = {float(std::cos(half)), float(std::sin(half)), 0.0f, 0.0f};
  // THEN each is refused as an implausible step; the same message without damage passes
  EXPECT_EQ(verdictAfterGoodRun(q, acc_doubled, gyr), FramePlausibility::Verdict::kImplausibleStep);
  EXPECT_EQ(verdictAfterGoodRun(q, acc_quartered, gyr), FramePlausibility::Verdict::kImplausibleStep);
  EXPECT_EQ(verdictAfterGoodRun(q, acc, gyr_spike), FramePlausibility::Verdict::kImplausibleStep);
  EXPECT_EQ(verdictAfterGoodRun(q_rolled, acc, gyr), FramePlausibility::Verdict::kImplausibleStep);
  EXPECT_EQ(verdictAfterGoodRun(q, acc, gyr), FramePlausibility::Verdict::kAccepted);
}

}  // namespace
}  // namespace deepnav
