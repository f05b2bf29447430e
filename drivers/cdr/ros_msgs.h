#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

// Plain mirrors of the ROS 2 messages deepnav records and replays, field for field, so that
// Foxglove, rosbag2 and ros2 tools read our recordings. Frames and units are those of ROS
// (REP 103/105): metres, radians, seconds, Pascal; covariances row-major.
// kTypeName is the schema name written to MCAP.
namespace deepnav::ros {

struct Time {  // builtin_interfaces/msg/Time
  int32_t sec = 0;
  uint32_t nanosec = 0;
};

struct Header {  // std_msgs/msg/Header
  static constexpr std::string_view kTypeName = "std_msgs/msg/Header";
  Time stamp;
  std::string frame_id;
};

struct Vector3 {  // geometry_msgs/msg/Vector3
  double x = 0, y = 0, z = 0;
};

struct Point {  // geometry_msgs/msg/Point
  double x = 0, y = 0, z = 0;
};

struct Quaternion {  // geometry_msgs/msg/Quaternion
  double x = 0, y = 0, z = 0, w = 1;
};

struct Pose {  // geometry_msgs/msg/Pose
  Point position;
  Quaternion orientation;
};

struct PoseWithCovariance {  // geometry_msgs/msg/PoseWithCovariance
  Pose pose;
  std::array<double, 36> covariance{};  // x, y, z, rot x, rot y, rot z
};

struct Twist {  // geometry_msgs/msg/Twist
  Vector3 linear;
  Vector3 angular;
};

struct TwistWithCovariance {  // geometry_msgs/msg/TwistWithCovariance
  Twist twist;
  std::array<double, 36> covariance{};
};

struct TwistWithCovarianceStamped {
  static constexpr std::string_view kTypeName = "geometry_msgs/msg/TwistWithCovarianceStamped";
  Header header;
  TwistWithCovariance twist;
};

struct Imu {
  static constexpr std::string_view kTypeName = "sensor_msgs/msg/Imu";
  Header header;
  Quaternion orientation;
  std::array<double, 9> orientation_covariance{};  // [0] = -1: no orientation estimate
  Vector3 angular_velocity;                        // rad/s
  std::array<double, 9> angular_velocity_covariance{};
  Vector3 linear_acceleration;  // m/s^2
  std::array<double, 9> linear_acceleration_covariance{};
};

struct Image {
  static constexpr std::string_view kTypeName = "sensor_msgs/msg/Image";
  Header header;
  uint32_t height = 0;
  uint32_t width = 0;
  std::string encoding;  // "mono8", "bgr8", ...
  uint8_t is_bigendian = 0;
  uint32_t step = 0;  // bytes per row
  std::vector<uint8_t> data;
};

// Image to encode straight from a frame buffer, without copying the pixels into an Image first.
struct ImageView {
  static constexpr std::string_view kTypeName = Image::kTypeName;
  const Header* header = nullptr;
  uint32_t height = 0;
  uint32_t width = 0;
  std::string_view encoding;
  uint8_t is_bigendian = 0;
  uint32_t step = 0;
  const uint8_t* data = nullptr;
  size_t size = 0;
};

struct FluidPressure {
  static constexpr std::string_view kTypeName = "sensor_msgs/msg/FluidPressure";
  Header header;
  double fluid_pressure = 0;  // Pa
  double variance = 0;        // Pa^2; 0 = unknown
};

struct Odometry {
  static constexpr std::string_view kTypeName = "nav_msgs/msg/Odometry";
  Header header;               // frame of the pose
  std::string child_frame_id;  // frame of the twist
  PoseWithCovariance pose;
  TwistWithCovariance twist;
};

struct TwistStamped {  // geometry_msgs/msg/TwistStamped (DVL velocity without covariance)
  static constexpr std::string_view kTypeName = "geometry_msgs/msg/TwistStamped";
  Header header;
  Twist twist;
};

struct CompressedImage {
  static constexpr std::string_view kTypeName = "sensor_msgs/msg/CompressedImage";
  Header header;
  std::string format;  // "jpeg", "png", or image_transport's "mono8; jpeg compressed mono8"
  std::vector<uint8_t> data;
};

struct MagneticField {
  static constexpr std::string_view kTypeName = "sensor_msgs/msg/MagneticField";
  Header header;
  Vector3 magnetic_field;  // tesla
  std::array<double, 9> magnetic_field_covariance{};  // [0] = 0: unknown
};

}  // namespace deepnav::ros
