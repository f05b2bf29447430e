#pragma once
// Test scaffolding: ROS 1 serialization of the message structs of drivers/cdr/ros_msgs.h, written
// independently of the reader's decoder (drivers/rosbag/ros1_msg_codec.cpp) so that a round trip
// checks one against the other. ROS 1: little-endian, packed, uint32 length before strings and
// variable arrays, none before fixed arrays; std_msgs/Header = uint32 seq, time (uint32 sec,
// uint32 nsec), string frame_id.
#include <bit>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/cdr/ros_msgs.h"

namespace deepnav::testsupport {

class Ros1Encoder {
 public:
  void u8(uint8_t v) { out_.push_back(v); }
  void u32(uint32_t v) {
    for (int i = 0; i < 4; ++i) out_.push_back(uint8_t(v >> (8 * i)));
  }
  void u64(uint64_t v) {
    for (int i = 0; i < 8; ++i) out_.push_back(uint8_t(v >> (8 * i)));
  }
  void f64(double v) { u64(std::bit_cast<uint64_t>(v)); }
  void string(std::string_view s) {
    u32(uint32_t(s.size()));
    out_.insert(out_.end(), s.begin(), s.end());
  }
  void bytes(const std::vector<uint8_t>& b) {
    u32(uint32_t(b.size()));
    out_.insert(out_.end(), b.begin(), b.end());
  }
  template <size_t N>
  void f64s(const std::array<double, N>& a) {
    for (double v : a) f64(v);
  }
  void vector3(const ros::Vector3& v) {
    f64(v.x);
    f64(v.y);
    f64(v.z);
  }
  void header(const ros::Header& h, uint32_t seq) {
    u32(seq);
    u32(uint32_t(h.stamp.sec));
    u32(h.stamp.nanosec);
    string(h.frame_id);
  }
  std::vector<uint8_t> take() { return std::move(out_); }

 private:
  std::vector<uint8_t> out_;
};

// The ROS 1 name, md5sum and message_definition a recorder writes in the connection record.
// md5sums computed by the ROS md5 rule (wiki.ros.org/ROS/Technical Overview) with Python's
// hashlib from the definitions below; they match what `rosbag info` prints for these types.
template <class Msg>
struct Ros1Type;

inline constexpr std::string_view kRos1HeaderDefinition =
    "================================================================================\n"
    "MSG: std_msgs/Header\nuint32 seq\ntime stamp\nstring frame_id\n";
inline constexpr std::string_view kRos1Vector3Definition =
    "================================================================================\n"
    "MSG: geometry_msgs/Vector3\nfloat64 x\nfloat64 y\nfloat64 z\n";

template <>
struct Ros1Type<ros::Image> {
  static constexpr std::string_view kName = "sensor_msgs/Image";
  static constexpr std::string_view kMd5 = "060021388200f6f0f447d0fcd9c64743";
  static std::string definition() {
    return "Header header\nuint32 height\nuint32 width\nstring encoding\nuint8 is_bigendian\n"
           "uint32 step\nuint8[] data\n" + std::string(kRos1HeaderDefinition);
  }
  static void encode(Ros1Encoder& e, const ros::Image& m, uint32_t seq) {
    e.header(m.header, seq);
    e.u32(m.height);
    e.u32(m.width);
    e.string(m.encoding);
    e.u8(m.is_bigendian);
    e.u32(m.step);
    e.bytes(m.data);
  }
};

template <>
struct Ros1Type<ros::CompressedImage> {
  static constexpr std::string_view kName = "sensor_msgs/CompressedImage";
  static constexpr std::string_view kMd5 = "8f7a12909da2c9d3332d540a0977563f";
  static std::string definition() {
    return "Header header\nstring format\nuint8[] data\n" + std::string(kRos1HeaderDefinition);
  }
  static void encode(Ros1Encoder& e, const ros::CompressedImage& m, uint32_t seq) {
    e.header(m.header, seq);
    e.string(m.format);
    e.bytes(m.data);
  }
};

template <>
struct Ros1Type<ros::Imu> {
  static constexpr std::string_view kName = "sensor_msgs/Imu";
  static constexpr std::string_view kMd5 = "6a62c6daae103f4ff57a132d6f95cec2";
  static std::string definition() {
    return "Header header\ngeometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n"
           "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n"
           "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n" +
           std::string(kRos1HeaderDefinition) +
           "================================================================================\n"
           "MSG: geometry_msgs/Quaternion\nfloat64 x\nfloat64 y\nfloat64 z\nfloat64 w\n" +
           std::string(kRos1Vector3Definition);
  }
  static void encode(Ros1Encoder& e, const ros::Imu& m, uint32_t seq) {
    e.header(m.header, seq);
    e.f64(m.orientation.x);
    e.f64(m.orientation.y);
    e.f64(m.orientation.z);
    e.f64(m.orientation.w);
    e.f64s(m.orientation_covariance);
    e.vector3(m.angular_velocity);
    e.f64s(m.angular_velocity_covariance);
    e.vector3(m.linear_acceleration);
    e.f64s(m.linear_acceleration_covariance);
  }
};

template <>
struct Ros1Type<ros::FluidPressure> {
  static constexpr std::string_view kName = "sensor_msgs/FluidPressure";
  static constexpr std::string_view kMd5 = "804dc5cea1c5306d6a2eb80b9833befe";
  static std::string definition() {
    return "Header header\nfloat64 fluid_pressure\nfloat64 variance\n" +
           std::string(kRos1HeaderDefinition);
  }
  static void encode(Ros1Encoder& e, const ros::FluidPressure& m, uint32_t seq) {
    e.header(m.header, seq);
    e.f64(m.fluid_pressure);
    e.f64(m.variance);
  }
};

template <>
struct Ros1Type<ros::MagneticField> {
  static constexpr std::string_view kName = "sensor_msgs/MagneticField";
  static constexpr std::string_view kMd5 = "2f3b0b43eed0c9501de0fa3ff89a45aa";
  static std::string definition() {
    return "Header header\ngeometry_msgs/Vector3 magnetic_field\n"
           "float64[9] magnetic_field_covariance\n" +
           std::string(kRos1HeaderDefinition) + std::string(kRos1Vector3Definition);
  }
  static void encode(Ros1Encoder& e, const ros::MagneticField& m, uint32_t seq) {
    e.header(m.header, seq);
    e.vector3(m.magnetic_field);
    e.f64s(m.magnetic_field_covariance);
  }
};

inline std::string ros1TwistDefinition() {
  return "================================================================================\n"
         "MSG: geometry_msgs/Twist\ngeometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n" +
         std::string(kRos1Vector3Definition);
}

template <>
struct Ros1Type<ros::TwistStamped> {
  static constexpr std::string_view kName = "geometry_msgs/TwistStamped";
  static constexpr std::string_view kMd5 = "98d34b0043a2093cf9d9345ab6eef12e";
  static std::string definition() {
    return "Header header\nTwist twist\n" + std::string(kRos1HeaderDefinition) +
           ros1TwistDefinition();
  }
  static void encode(Ros1Encoder& e, const ros::TwistStamped& m, uint32_t seq) {
    e.header(m.header, seq);
    e.vector3(m.twist.linear);
    e.vector3(m.twist.angular);
  }
};

template <>
struct Ros1Type<ros::TwistWithCovarianceStamped> {
  static constexpr std::string_view kName = "geometry_msgs/TwistWithCovarianceStamped";
  static constexpr std::string_view kMd5 = "8927a1a12fb2607ceea095b2dc440a96";
  static std::string definition() {
    return "Header header\nTwistWithCovariance twist\n" + std::string(kRos1HeaderDefinition) +
           "================================================================================\n"
           "MSG: geometry_msgs/TwistWithCovariance\nTwist twist\nfloat64[36] covariance\n" +
           ros1TwistDefinition();
  }
  static void encode(Ros1Encoder& e, const ros::TwistWithCovarianceStamped& m, uint32_t seq) {
    e.header(m.header, seq);
    e.vector3(m.twist.twist.linear);
    e.vector3(m.twist.twist.angular);
    e.f64s(m.twist.covariance);
  }
};

template <class Msg>
std::vector<uint8_t> encodeRos1(const Msg& msg, uint32_t seq = 0) {
  Ros1Encoder e;
  Ros1Type<Msg>::encode(e, msg, seq);
  return e.take();
}

}  // namespace deepnav::testsupport
