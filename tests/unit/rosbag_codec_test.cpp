// ROS 1 message decoding (drivers/rosbag/ros1_msg_codec.h) against malformed input: every prefix
// of a valid message is too short, a trailing byte is too long, a length past the end, a time the
// structs cannot hold.
#include <gtest/gtest.h>

#include "drivers/rosbag/ros1_msg_codec.h"
#include "tests/support/ros1_msg_encoder.h"
#include "tests/unit/rosbag_test_util.h"

namespace deepnav::rosbag {
namespace {

using testsupport::encodeRos1;
using namespace testing_util;

template <class Msg>
void expectOnlyTheWholeMessageDecodes(const Msg& sent) {
  std::vector<uint8_t> bytes = encodeRos1(sent, 42);
  Msg got;
  ASSERT_TRUE(decodeRos1(bytes.data(), bytes.size(), &got));
  EXPECT_EQ(encodeRos1(got, 42), bytes);
  for (size_t n = 0; n < bytes.size(); ++n) {
    EXPECT_FALSE(decodeRos1(bytes.data(), n, &got)) << "prefix of " << n << " bytes";
  }
  bytes.push_back(0);
  EXPECT_FALSE(decodeRos1(bytes.data(), bytes.size(), &got)) << "a trailing byte";
}

TEST(RosbagRos1Codec, EveryTypeRefusesTruncatedOrOverlongMessages) {
  expectOnlyTheWholeMessageDecodes(sampleImu(1));
  expectOnlyTheWholeMessageDecodes(sampleImage(1));
  expectOnlyTheWholeMessageDecodes(sampleCompressedImage(1));
  expectOnlyTheWholeMessageDecodes(sampleFluidPressure(1));
  expectOnlyTheWholeMessageDecodes(sampleTwistStamped(1));
  expectOnlyTheWholeMessageDecodes(sampleTwistWithCovariance(1));
  expectOnlyTheWholeMessageDecodes(sampleMagneticField(1));
}

TEST(RosbagRos1Codec, HeaderLayoutIsSeqSecNsecFrame) {
  const std::vector<uint8_t> bytes = encodeRos1(sampleFluidPressure(0), 7);
  // seq 7, sec 1700000300, nsec 8, frame_id "depth" (length 5), then two float64.
  ASSERT_EQ(bytes.size(), 4u + 4u + 4u + 4u + 5u + 16u);
  EXPECT_EQ(bytes[0], 7);
  EXPECT_EQ(bytes[8], 8);
  EXPECT_EQ(bytes[12], 5);
  EXPECT_EQ(std::string(bytes.begin() + 16, bytes.begin() + 21), "depth");
  ros::FluidPressure got;
  ASSERT_TRUE(decodeRos1(bytes.data(), bytes.size(), &got));
  EXPECT_EQ(got.header.stamp.sec, 1700000300);
  EXPECT_EQ(got.header.stamp.nanosec, 8u);
  EXPECT_EQ(got.header.frame_id, "depth");
  EXPECT_EQ(got.fluid_pressure, 101325.0);
  EXPECT_EQ(got.variance, 4.5);
}

TEST(RosbagRos1Codec, LengthPastTheEndIsRefused) {
  std::vector<uint8_t> bytes = encodeRos1(sampleImage(0));
  // The data array's uint32 length sits 12 bytes before the end (12 pixels): claim 13.
  bytes[bytes.size() - 16] = 13;
  ros::Image got;
  EXPECT_FALSE(decodeRos1(bytes.data(), bytes.size(), &got));
  bytes[bytes.size() - 16] = 12;
  EXPECT_TRUE(decodeRos1(bytes.data(), bytes.size(), &got));
  EXPECT_EQ(got.data.size(), 12u);
}

TEST(RosbagRos1Codec, TimeTheStructsCannotHoldIsRefused) {
  ros::Imu m = sampleImu(0);
  std::vector<uint8_t> bytes = encodeRos1(m);
  bytes[8] = 0x00;  // nsec = 1e9 (0x3B9ACA00)
  bytes[9] = 0xCA;
  bytes[10] = 0x9A;
  bytes[11] = 0x3B;
  ros::Imu got;
  EXPECT_FALSE(decodeRos1(bytes.data(), bytes.size(), &got));
  bytes = encodeRos1(m);
  bytes[7] = 0x80;  // sec >= 2^31
  EXPECT_FALSE(decodeRos1(bytes.data(), bytes.size(), &got));
}

}  // namespace
}  // namespace deepnav::rosbag
