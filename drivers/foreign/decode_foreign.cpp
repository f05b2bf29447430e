#include "drivers/foreign/decode_foreign.h"

#include "drivers/cdr/ros_msg_codec.h"
#include "drivers/rosbag/ros1_msg_codec.h"

namespace deepnav::foreign {
namespace {

template <typename Msg>
bool decodeAny(const ForeignMessage& m, Msg* out) {
  switch (m.serialization) {
    case Serialization::kCdr:
      return ros::decode(m.data, m.size, out);
    case Serialization::kRos1:
      return rosbag::decodeRos1(m.data, m.size, out);
  }
  return false;
}

}  // namespace

bool decodeForeign(const ForeignMessage& m, ros::Imu* out) { return decodeAny(m, out); }
bool decodeForeign(const ForeignMessage& m, ros::Image* out) { return decodeAny(m, out); }
bool decodeForeign(const ForeignMessage& m, ros::CompressedImage* out) { return decodeAny(m, out); }
bool decodeForeign(const ForeignMessage& m, ros::FluidPressure* out) { return decodeAny(m, out); }
bool decodeForeign(const ForeignMessage& m, ros::TwistStamped* out) { return decodeAny(m, out); }
bool decodeForeign(const ForeignMessage& m, ros::TwistWithCovarianceStamped* out) { return decodeAny(m, out); }
bool decodeForeign(const ForeignMessage& m, ros::MagneticField* out) { return decodeAny(m, out); }

bool sameRosType(std::string_view file_type, std::string_view ros2_name) {
  if (file_type == ros2_name) return true;
  const std::size_t msg = ros2_name.find("/msg/");
  if (msg == std::string_view::npos) return false;
  const std::string_view package = ros2_name.substr(0, msg);
  const std::string_view name = ros2_name.substr(msg + 5);
  return file_type.size() == package.size() + 1 + name.size() && file_type.substr(0, package.size()) == package &&
         file_type[package.size()] == '/' && file_type.substr(package.size() + 1) == name;
}

}  // namespace deepnav::foreign
