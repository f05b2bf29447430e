// CDR encoding of the ROS 2 messages: byte-exact layout (alignment!), round trips of every type,
// and bounds-checked decoding of short or foreign input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

#include "drivers/cdr/cdr_reader.h"
#include "drivers/cdr/cdr_writer.h"
#include "drivers/cdr/ros_msg_codec.h"

namespace deepnav::ros {
namespace {

Header makeHeader(int32_t sec, uint32_t nanosec, std::string frame) {
  Header h;
  h.stamp = Time{sec, nanosec};
  h.frame_id = std::move(frame);
  return h;
}

template <size_t N>
std::array<double, N> ramp(double start) {
  std::array<double, N> a{};
  for (size_t i = 0; i < N; ++i) a[i] = start + double(i) * 0.5;
  return a;
}

void expectEqual(const Header& a, const Header& b) {
  EXPECT_EQ(a.stamp.sec, b.stamp.sec);
  EXPECT_EQ(a.stamp.nanosec, b.stamp.nanosec);
  EXPECT_EQ(a.frame_id, b.frame_id);
}

void expectEqual(const Vector3& a, const Vector3& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
}

void expectEqual(const Quaternion& a, const Quaternion& b) {
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.w, b.w);
}

void expectEqual(const TwistWithCovariance& a, const TwistWithCovariance& b) {
  expectEqual(a.twist.linear, b.twist.linear);
  expectEqual(a.twist.angular, b.twist.angular);
  EXPECT_EQ(a.covariance, b.covariance);
}

// Every message must decode from its own encoding and from nothing shorter.
template <typename Msg>
std::vector<uint8_t> encodeAndCheckShortInputs(const Msg& m) {
  std::vector<uint8_t> bytes;
  EXPECT_TRUE(encode(m, &bytes));
  EXPECT_EQ(bytes.size(), encodedSize(m));
  for (size_t n = 0; n < bytes.size(); ++n) {
    Msg ignored;
    // Trailing alignment padding is the only thing a decoder may do without.
    if (decode(bytes.data(), n, &ignored)) {
      EXPECT_GE(n + 8, bytes.size()) << "decoded from " << n << " of " << bytes.size() << " bytes";
    }
  }
  return bytes;
}

TEST(CdrWriter, FluidPressureMatchesHandComputedBytes) {
  FluidPressure m;
  m.header = makeHeader(1, 2, "ab");
  m.fluid_pressure = 1.5;
  m.variance = 0.25;
  const std::vector<uint8_t> expected = {
      0x00, 0x01, 0x00, 0x00,                          // encapsulation: CDR_LE
      0x01, 0x00, 0x00, 0x00,                          // stamp.sec = 1
      0x02, 0x00, 0x00, 0x00,                          // stamp.nanosec = 2
      0x03, 0x00, 0x00, 0x00, 'a',  'b',  0x00,        // frame_id: length 3 incl. NUL
      0x00,                                            // pad to 8 (offset 15 -> 16 after header)
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0x3F,  // fluid_pressure = 1.5
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0x3F,  // variance = 0.25
  };
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(encode(m, &bytes));
  EXPECT_EQ(bytes, expected);
}

TEST(CdrWriter, EmptyStringIsLengthOneAndNul) {
  uint8_t buffer[16] = {};
  cdr::CdrWriter w(buffer, sizeof(buffer));
  w.u8(9);
  w.string("");
  w.u16(0x0102);
  ASSERT_TRUE(w.ok());
  const std::vector<uint8_t> expected = {0, 1, 0, 0, 9, 0, 0, 0, 1, 0, 0, 0, 0, 0, 2, 1};
  EXPECT_EQ(std::vector<uint8_t>(buffer, buffer + w.size()), expected);
}

TEST(CdrWriter, RefusesToWritePastItsBufferButStillMeasures) {
  Imu m;
  m.header = makeHeader(3, 4, "imu_link");
  std::vector<uint8_t> small(40, 0xEE);
  EXPECT_EQ(encode(m, small.data(), small.size()), 0u);
  std::fill(small.begin(), small.end(), 0xEE);
  cdr::CdrWriter w(small.data(), 8);
  encodeFields(w, m);
  EXPECT_FALSE(w.ok());
  EXPECT_EQ(w.size(), encodedSize(m));
  EXPECT_EQ(small[8], 0xEE);  // nothing written past the capacity
}

TEST(CdrRoundTrip, Imu) {
  Imu m;
  m.header = makeHeader(1700000000, 123456789, "imu_link");
  m.orientation = Quaternion{0.1, -0.2, 0.3, 0.9};
  m.orientation_covariance = ramp<9>(1);
  m.angular_velocity = Vector3{0.01, 0.02, -0.03};
  m.angular_velocity_covariance = ramp<9>(2);
  m.linear_acceleration = Vector3{0.1, 0.2, 9.81};
  m.linear_acceleration_covariance = ramp<9>(3);
  const std::vector<uint8_t> bytes = encodeAndCheckShortInputs(m);
  Imu d;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d));
  expectEqual(d.header, m.header);
  expectEqual(d.orientation, m.orientation);
  expectEqual(d.angular_velocity, m.angular_velocity);
  expectEqual(d.linear_acceleration, m.linear_acceleration);
  EXPECT_EQ(d.orientation_covariance, m.orientation_covariance);
  EXPECT_EQ(d.angular_velocity_covariance, m.angular_velocity_covariance);
  EXPECT_EQ(d.linear_acceleration_covariance, m.linear_acceleration_covariance);
  // "imu_link" (9 bytes with NUL) ends at 21 after the header: 3 pad bytes before the doubles.
  EXPECT_EQ(bytes.size(), 4u + 4 + 4 + 4 + 9 + 3 + 8 * (4 + 9 + 3 + 9 + 3 + 9));
}

TEST(CdrRoundTrip, Image) {
  Image m;
  m.header = makeHeader(5, 6, "cam_left");
  m.height = 3;
  m.width = 5;
  m.encoding = "mono8";
  m.is_bigendian = 0;
  m.step = 5;
  for (int i = 0; i < 15; ++i) m.data.push_back(uint8_t(i * 17));
  const std::vector<uint8_t> bytes = encodeAndCheckShortInputs(m);
  Image d;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d));
  expectEqual(d.header, m.header);
  EXPECT_EQ(d.height, m.height);
  EXPECT_EQ(d.width, m.width);
  EXPECT_EQ(d.encoding, m.encoding);
  EXPECT_EQ(d.is_bigendian, m.is_bigendian);
  EXPECT_EQ(d.step, m.step);
  EXPECT_EQ(d.data, m.data);

  // An ImageView of the same pixels encodes to the same bytes, with no copy into an Image.
  const ImageView view{&m.header,      m.height, m.width,       m.encoding,
                       m.is_bigendian, m.step,   m.data.data(), m.data.size()};
  std::vector<uint8_t> view_bytes;
  ASSERT_TRUE(encode(view, &view_bytes));
  EXPECT_EQ(view_bytes, bytes);
}

TEST(CdrRoundTrip, FluidPressure) {
  FluidPressure m;
  m.header = makeHeader(-1, 999999999, "depth_sensor");
  m.fluid_pressure = 201325.5;
  m.variance = 4.0;
  const std::vector<uint8_t> bytes = encodeAndCheckShortInputs(m);
  FluidPressure d;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d));
  expectEqual(d.header, m.header);
  EXPECT_EQ(d.fluid_pressure, m.fluid_pressure);
  EXPECT_EQ(d.variance, m.variance);
}

TEST(CdrRoundTrip, TwistWithCovarianceStamped) {
  TwistWithCovarianceStamped m;
  m.header = makeHeader(10, 20, "dvl");
  m.twist.twist.linear = Vector3{0.5, -0.25, 0.125};
  m.twist.twist.angular = Vector3{0, 0, 0.01};
  m.twist.covariance = ramp<36>(-3);
  const std::vector<uint8_t> bytes = encodeAndCheckShortInputs(m);
  TwistWithCovarianceStamped d;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d));
  expectEqual(d.header, m.header);
  expectEqual(d.twist, m.twist);
}

TEST(CdrRoundTrip, Odometry) {
  Odometry m;
  m.header = makeHeader(100, 200, "odom");
  m.child_frame_id = "base_link";
  m.pose.pose.position = Point{1, 2, -30};
  m.pose.pose.orientation = Quaternion{0, 0, 0.7071067811865476, 0.7071067811865476};
  m.pose.covariance = ramp<36>(0);
  m.twist.twist.linear = Vector3{0.3, 0, 0};
  m.twist.covariance = ramp<36>(100);
  const std::vector<uint8_t> bytes = encodeAndCheckShortInputs(m);
  Odometry d;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &d));
  expectEqual(d.header, m.header);
  EXPECT_EQ(d.child_frame_id, m.child_frame_id);
  EXPECT_EQ(d.pose.pose.position.x, 1);
  EXPECT_EQ(d.pose.pose.position.z, -30);
  expectEqual(d.pose.pose.orientation, m.pose.pose.orientation);
  EXPECT_EQ(d.pose.covariance, m.pose.covariance);
  expectEqual(d.twist, m.twist);
}

TEST(CdrReader, RefusesOtherEncapsulationsAndBadStrings) {
  FluidPressure m;
  m.header = makeHeader(1, 2, "ab");
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(encode(m, &bytes));
  FluidPressure d;
  std::vector<uint8_t> big_endian = bytes;
  big_endian[1] = 0x00;  // CDR_BE
  EXPECT_FALSE(decode(big_endian.data(), big_endian.size(), &d));
  std::vector<uint8_t> no_nul = bytes;
  no_nul[18] = 'c';  // the frame_id's terminator
  EXPECT_FALSE(decode(no_nul.data(), no_nul.size(), &d));
  std::vector<uint8_t> huge_string = bytes;
  huge_string[15] = 0x7F;  // frame_id length ~2 GB
  EXPECT_FALSE(decode(huge_string.data(), huge_string.size(), &d));
}

TEST(CdrReader, RefusesASequenceCountLargerThanTheInput) {
  Image m;
  m.data.assign(10, 1);
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(encode(m, &bytes));
  // The data count sits right before the last 10 bytes.
  bytes[bytes.size() - 14] = 0xFF;
  bytes[bytes.size() - 13] = 0xFF;
  Image d;
  EXPECT_FALSE(decode(bytes.data(), bytes.size(), &d));
}

TEST(CdrCustom, ProjectMessageWithHeaderAndPrimitives) {
  // A project message: std_msgs/Header header, uint8 mode, float64 depth_m, int32[] flags.
  const Header header = makeHeader(7, 8, "nav");
  const std::vector<int32_t> flags = {1, -2, 3};
  const auto write = [&](cdr::CdrWriter& w) {
    encodeFields(w, header);
    w.u8(2);
    w.f64(12.75);
    w.sequenceLength(flags.size());
    for (const int32_t f : flags) w.i32(f);
  };
  const size_t size = encodeCustom(nullptr, 0, write);
  ASSERT_GT(size, 0u);
  std::vector<uint8_t> bytes(size);
  ASSERT_EQ(encodeCustom(bytes.data(), bytes.size(), write), size);

  cdr::CdrReader r(bytes.data(), bytes.size());
  Header h;
  uint8_t mode = 0;
  double depth_m = 0;
  uint32_t count = 0;
  ASSERT_TRUE(decodeFields(r, &h) && r.u8(&mode) && r.f64(&depth_m) && r.sequenceLength(&count, 4));
  ASSERT_EQ(count, 3u);
  std::vector<int32_t> got(count);
  for (int32_t& f : got) ASSERT_TRUE(r.i32(&f));
  expectEqual(h, header);
  EXPECT_EQ(mode, 2);
  EXPECT_EQ(depth_m, 12.75);
  EXPECT_EQ(got, flags);
  EXPECT_EQ(r.remaining(), 0u);
}

}  // namespace
}  // namespace deepnav::ros
