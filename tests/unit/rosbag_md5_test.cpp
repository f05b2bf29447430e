// The md5sums drivers/rosbag checks connections against (ros1_md5.cpp), recomputed here by the ROS
// rule (wiki.ros.org/ROS/Technical Overview, "Message serialization and msg MD5 sums"): the md5 of
// the definition's text without comments, one "type name" per line, each embedded message type
// replaced by its own md5sum (arrays of builtins keep their "[N]"/"[]").
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>

#include "drivers/rosbag/ros1_md5.h"

namespace deepnav::rosbag {
namespace {

// MD5 (RFC 1321), enough for short texts.
std::string md5Hex(std::string_view text) {
  static constexpr std::array<uint32_t, 64> kShift = {
      7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22, 7, 12, 17, 22, 5, 9,  14, 20, 5, 9,
      14, 20, 5, 9,  14, 20, 5, 9,  14, 20, 4, 11, 16, 23, 4, 11, 16, 23, 4, 11, 16, 23,
      4, 11, 16, 23, 6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21, 6, 10, 15, 21};
  std::array<uint32_t, 64> k{};
  for (size_t i = 0; i < 64; ++i) {
    // K[i] = floor(2^32 * |sin(i + 1)|), as the RFC defines the table.
    k[i] = uint32_t(uint64_t(4294967296.0 * std::abs(std::sin(double(i + 1)))));
  }
  std::string msg(text);
  const uint64_t bits = uint64_t(text.size()) * 8;
  msg.push_back(char(0x80));
  while (msg.size() % 64 != 56) msg.push_back(0);
  for (int i = 0; i < 8; ++i) msg.push_back(char(bits >> (8 * i)));
  uint32_t h[4] = {0x67452301, 0xefcdab89, 0x98badcfe, 0x10325476};
  for (size_t block = 0; block < msg.size(); block += 64) {
    uint32_t w[16];
    for (int i = 0; i < 16; ++i) {
      const auto* p = reinterpret_cast<const uint8_t*>(msg.data() + block + 4 * i);
      w[i] = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
    }
    uint32_t a = h[0], b = h[1], c = h[2], d = h[3];
    for (uint32_t i = 0; i < 64; ++i) {
      uint32_t f = 0, g = 0;
      if (i < 16) {
        f = (b & c) | (~b & d), g = i;
      } else if (i < 32) {
        f = (d & b) | (~d & c), g = (5 * i + 1) % 16;
      } else if (i < 48) {
        f = b ^ c ^ d, g = (3 * i + 5) % 16;
      } else {
        f = c ^ (b | ~d), g = (7 * i) % 16;
      }
      const uint32_t x = a + f + k[i] + w[g];
      a = d;
      d = c;
      c = b;
      b = b + ((x << kShift[i]) | (x >> (32 - kShift[i])));
    }
    h[0] += a, h[1] += b, h[2] += c, h[3] += d;
  }
  std::string hex;
  for (uint32_t v : h) {
    for (int i = 0; i < 4; ++i) {
      static constexpr char kDigits[] = "0123456789abcdef";
      const uint8_t byte = uint8_t(v >> (8 * i));
      hex += kDigits[byte >> 4];
      hex += kDigits[byte & 15];
    }
  }
  return hex;
}

TEST(RosbagMd5Rule, Md5MatchesTheRfcVectors) {
  EXPECT_EQ(md5Hex(""), "d41d8cd98f00b204e9800998ecf8427e");
  EXPECT_EQ(md5Hex("abc"), "900150983cd24fb0d6963f7d28e17f72");
  EXPECT_EQ(md5Hex("12345678901234567890123456789012345678901234567890123456789012345678901234567890"),
            "57edf4a22be3c955ac49da2e2107b67a");
}

TEST(RosbagMd5Rule, StandardTableFollowsFromTheDefinitions) {
  const std::string header = md5Hex("uint32 seq\ntime stamp\nstring frame_id");
  const std::string quaternion = md5Hex("float64 x\nfloat64 y\nfloat64 z\nfloat64 w");
  const std::string vector3 = md5Hex("float64 x\nfloat64 y\nfloat64 z");
  const std::string twist = md5Hex(vector3 + " linear\n" + vector3 + " angular");
  const std::string twist_cov = md5Hex(twist + " twist\nfloat64[36] covariance");
  EXPECT_EQ(header, "2176decaecbce78abc3b96ef049fabed");

  EXPECT_EQ(standardMd5("sensor_msgs/Imu"),
            md5Hex(header + " header\n" + quaternion + " orientation\n" +
                   "float64[9] orientation_covariance\n" + vector3 + " angular_velocity\n" +
                   "float64[9] angular_velocity_covariance\n" + vector3 +
                   " linear_acceleration\nfloat64[9] linear_acceleration_covariance"));
  EXPECT_EQ(standardMd5("sensor_msgs/Image"),
            md5Hex(header + " header\nuint32 height\nuint32 width\nstring encoding\n"
                            "uint8 is_bigendian\nuint32 step\nuint8[] data"));
  EXPECT_EQ(standardMd5("sensor_msgs/CompressedImage"),
            md5Hex(header + " header\nstring format\nuint8[] data"));
  EXPECT_EQ(standardMd5("sensor_msgs/FluidPressure"),
            md5Hex(header + " header\nfloat64 fluid_pressure\nfloat64 variance"));
  EXPECT_EQ(standardMd5("sensor_msgs/MagneticField"),
            md5Hex(header + " header\n" + vector3 +
                   " magnetic_field\nfloat64[9] magnetic_field_covariance"));
  EXPECT_EQ(standardMd5("geometry_msgs/TwistStamped"), md5Hex(header + " header\n" + twist + " twist"));
  EXPECT_EQ(standardMd5("geometry_msgs/TwistWithCovarianceStamped"),
            md5Hex(header + " header\n" + twist_cov + " twist"));
}

TEST(RosbagMd5Rule, CheckLayoutNamesTheTopic) {
  std::string error;
  EXPECT_TRUE(checkLayout("/imu", "sensor_msgs/Imu", "6a62c6daae103f4ff57a132d6f95cec2", &error));
  EXPECT_TRUE(checkLayout("/tf", "tf2_msgs/TFMessage", "anything", &error));
  EXPECT_FALSE(checkLayout("/imu", "sensor_msgs/Imu", "00000000000000000000000000000000", &error));
  EXPECT_NE(error.find("topic '/imu'"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::rosbag
