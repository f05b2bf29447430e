#include "drivers/rosbag/ros1_md5.h"

#include <array>
#include <utility>

namespace deepnav::rosbag {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kStandardMd5 = {{
    {"sensor_msgs/Image", "060021388200f6f0f447d0fcd9c64743"},
    {"sensor_msgs/CompressedImage", "8f7a12909da2c9d3332d540a0977563f"},
    {"sensor_msgs/Imu", "6a62c6daae103f4ff57a132d6f95cec2"},
    {"sensor_msgs/FluidPressure", "804dc5cea1c5306d6a2eb80b9833befe"},
    {"sensor_msgs/MagneticField", "2f3b0b43eed0c9501de0fa3ff89a45aa"},
    {"geometry_msgs/TwistStamped", "98d34b0043a2093cf9d9345ab6eef12e"},
    {"geometry_msgs/TwistWithCovarianceStamped", "8927a1a12fb2607ceea095b2dc440a96"},
}};

}  // namespace

std::string_view standardMd5(std::string_view ros1_type) {
  for (const auto& [type, md5] : kStandardMd5) {
    if (type == ros1_type) return md5;
  }
  return {};
}

bool checkLayout(std::string_view topic, std::string_view type, std::string_view md5sum,
                 std::string* error) {
  const std::string_view expected = standardMd5(type);
  if (expected.empty() || md5sum == expected || md5sum == "*") return true;
  *error = "topic '" + std::string(topic) + "': type " + std::string(type) + " has md5sum " +
           std::string(md5sum) + ", the standard " + std::string(type) + " has " +
           std::string(expected) + ": a different message layout, which deepnav cannot decode";
  return false;
}

}  // namespace deepnav::rosbag
