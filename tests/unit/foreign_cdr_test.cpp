// The ROS 2 messages added for foreign recordings (TwistStamped, CompressedImage, MagneticField): CDR round
// trips, byte layout, short input refused, and their ros2msg schema texts.
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "drivers/cdr/ros2msg_definitions.h"
#include "drivers/cdr/ros_msg_codec.h"

namespace deepnav::ros {
namespace {

Header header(int32_t sec, uint32_t nanosec, const char* frame) {
  Header h;
  h.stamp = {sec, nanosec};
  h.frame_id = frame;
  return h;
}

template <typename Msg>
std::vector<uint8_t> encodeChecked(const Msg& m) {
  std::vector<uint8_t> bytes;
  EXPECT_TRUE(encode(m, &bytes));
  EXPECT_EQ(bytes.size(), encodedSize(m));
  for (size_t n = 0; n < bytes.size(); ++n) {
    Msg back;
    EXPECT_FALSE(decode(bytes.data(), n, &back)) << "decoded from " << n << " of " << bytes.size() << " bytes";
  }
  return bytes;
}

TEST(ForeignCdr, TwistStampedRoundTripsWithTheDoublesAlignedAfterTheHeader) {
  TwistStamped m;
  m.header = header(1700000000, 123456789, "dvl");  // 4+4, string 4+4 ("dvl\0") = 16 bytes after encapsulation
  m.twist.linear = {0.5, -0.25, 0.125};
  m.twist.angular = {1e-3, -2e-3, 3e-3};
  const std::vector<uint8_t> bytes = encodeChecked(m);
  // Encapsulation 4 + header 16 = 20: the first double is aligned to 8 from the start of the payload (20 - 4 = 16).
  ASSERT_EQ(bytes.size(), 4u + 16u + 6u * 8u);
  double first = 0;
  std::memcpy(&first, bytes.data() + 20, 8);
  EXPECT_EQ(first, 0.5);
  TwistStamped back;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &back));
  EXPECT_EQ(back.header.stamp.sec, 1700000000);
  EXPECT_EQ(back.header.stamp.nanosec, 123456789u);
  EXPECT_EQ(back.header.frame_id, "dvl");
  EXPECT_EQ(back.twist.linear.y, -0.25);
  EXPECT_EQ(back.twist.angular.z, 3e-3);
}

TEST(ForeignCdr, CompressedImageRoundTripsFormatAndBytes) {
  CompressedImage m;
  m.header = header(5, 6, "cam_left");
  m.format = "bgr8; jpeg compressed bgr8";
  m.data = {0xFF, 0xD8, 0xFF, 0xE0, 1, 2, 3};
  const std::vector<uint8_t> bytes = encodeChecked(m);
  CompressedImage back;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &back));
  EXPECT_EQ(back.format, m.format);
  EXPECT_EQ(back.data, m.data);
  EXPECT_EQ(back.header.frame_id, "cam_left");
}

TEST(ForeignCdr, MagneticFieldRoundTripsFieldAndCovariance) {
  MagneticField m;
  m.header = header(7, 8, "mag");
  m.magnetic_field = {2.1e-5, -3.0e-6, -4.4e-5};
  for (size_t i = 0; i < 9; ++i) m.magnetic_field_covariance[i] = 1e-12 * static_cast<double>(i + 1);
  const std::vector<uint8_t> bytes = encodeChecked(m);
  EXPECT_EQ(bytes.size(), 4u + 16u + 3u * 8u + 9u * 8u);
  MagneticField back;
  ASSERT_TRUE(decode(bytes.data(), bytes.size(), &back));
  EXPECT_EQ(back.magnetic_field.z, -4.4e-5);
  EXPECT_EQ(back.magnetic_field_covariance, m.magnetic_field_covariance);
}

TEST(ForeignCdr, AMessageOfAnotherTypeDoesNotDecodeAsCompressedImage) {
  // An Imu's bytes read as a CompressedImage: the "format" string length is a double's bytes, far
  // beyond the message.
  Imu imu;
  imu.header = header(1, 2, "imu");
  imu.orientation = {0.1, 0.2, 0.3, 0.9};
  std::vector<uint8_t> bytes;
  ASSERT_TRUE(encode(imu, &bytes));
  CompressedImage wrong;
  EXPECT_FALSE(decode(bytes.data(), bytes.size(), &wrong));
}

TEST(ForeignCdr, SchemasOfTheNewTypesNameTheirDependencies) {
  const std::string twist = ros2MsgDefinition("geometry_msgs/msg/TwistStamped");
  EXPECT_EQ(twist.rfind("std_msgs/Header header\nTwist twist\n", 0), 0u) << twist;
  EXPECT_NE(twist.find("MSG: geometry_msgs/Twist\n"), std::string::npos);
  EXPECT_NE(twist.find("MSG: geometry_msgs/Vector3\n"), std::string::npos);
  EXPECT_NE(twist.find("MSG: std_msgs/Header\n"), std::string::npos);
  const std::string image = ros2MsgDefinition("sensor_msgs/msg/CompressedImage");
  EXPECT_NE(image.find("string format\n"), std::string::npos);
  EXPECT_NE(image.find("uint8[] data\n"), std::string::npos);
  const std::string mag = ros2MsgDefinition("sensor_msgs/msg/MagneticField");
  EXPECT_NE(mag.find("float64[9] magnetic_field_covariance\n"), std::string::npos);
  EXPECT_NE(mag.find("MSG: geometry_msgs/Vector3\n"), std::string::npos);
}

}  // namespace
}  // namespace deepnav::ros
