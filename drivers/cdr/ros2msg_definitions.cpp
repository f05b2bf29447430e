#include "drivers/cdr/ros2msg_definitions.h"

#include <cctype>
#include <functional>
#include <set>

namespace deepnav::ros {
namespace {

// Field lines of the upstream ROS 2 .msg files (Humble/Jazzy), keyed "pkg/Type".
const MsgDefinitions& standardDefinitions() {
  static const MsgDefinitions kDefinitions = {
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n"},
      {"geometry_msgs/Pose", "Point position\nQuaternion orientation\n"},
      {"geometry_msgs/PoseWithCovariance", "Pose pose\nfloat64[36] covariance\n"},
      {"geometry_msgs/Twist", "Vector3  linear\nVector3  angular\n"},
      {"geometry_msgs/TwistWithCovariance", "Twist twist\nfloat64[36] covariance\n"},
      {"geometry_msgs/TwistWithCovarianceStamped",
       "std_msgs/Header header\nTwistWithCovariance twist\n"},
      {"sensor_msgs/Imu",
       "std_msgs/Header header\n\n"
       "geometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n\n"
       "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n\n"
       "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n"},
      {"sensor_msgs/Image",
       "std_msgs/Header header\n\nuint32 height\nuint32 width\n\nstring encoding\n\n"
       "uint8 is_bigendian\nuint32 step\n\nuint8[] data\n"},
      {"sensor_msgs/FluidPressure",
       "std_msgs/Header header\n\nfloat64 fluid_pressure\nfloat64 variance\n"},
      {"geometry_msgs/TwistStamped", "std_msgs/Header header\nTwist twist\n"},
      {"sensor_msgs/CompressedImage", "std_msgs/Header header\n\nstring format\n\nuint8[] data\n"},
      {"sensor_msgs/MagneticField",
       "std_msgs/Header header\n\ngeometry_msgs/Vector3 magnetic_field\n\nfloat64[9] magnetic_field_covariance\n"},
      {"nav_msgs/Odometry",
       "std_msgs/Header header\nstring child_frame_id\n"
       "geometry_msgs/PoseWithCovariance pose\ngeometry_msgs/TwistWithCovariance twist\n"},
  };
  return kDefinitions;
}

bool isPrimitive(std::string_view type) {
  static const std::set<std::string_view> kPrimitives = {
      "bool",  "byte",   "char",  "float32", "float64", "int8",   "uint8",
      "int16", "uint16", "int32", "uint32",  "int64",   "uint64", "string"};
  return kPrimitives.count(type) != 0;
}

// "pkg/msg/Type" -> "pkg/Type"; "pkg/Type" stays.
std::string shortName(std::string_view type_name) {
  const size_t first = type_name.find('/');
  const size_t last = type_name.rfind('/');
  if (first == std::string_view::npos || first == last) return std::string(type_name);
  return std::string(type_name.substr(0, first)) + std::string(type_name.substr(last));
}

bool isTypeChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '/';
}

// The type of a field line ("  pkg/Type[3] name", "Type name", "uint8 X=1"), or "" for blank
// and comment lines. Mirrors rosbag2's pattern: type token, optional [..], then whitespace.
std::string_view fieldType(std::string_view line) {
  size_t i = 0;
  while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
  const size_t begin = i;
  while (i < line.size() && isTypeChar(line[i])) ++i;
  const std::string_view type = line.substr(begin, i - begin);
  if (type.empty()) return {};
  if (i < line.size() && line[i] == '[') {
    const size_t close = line.find(']', i);
    if (close == std::string_view::npos) return {};
    i = close + 1;
  }
  if (i >= line.size() || !std::isspace(static_cast<unsigned char>(line[i]))) return {};
  return type;
}

// Non-primitive field types of a .msg text, qualified with `package` when written bare, sorted.
std::set<std::string> dependencies(std::string_view text, std::string_view package) {
  std::set<std::string> deps;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view type = fieldType(text.substr(pos, end - pos));
    if (!type.empty() && !isPrimitive(type)) {
      deps.insert(type.find('/') == std::string_view::npos
                      ? std::string(package) + "/" + std::string(type)
                      : std::string(type));
    }
    pos = end + 1;
  }
  return deps;
}

const std::string* findDefinition(const std::string& short_name, const MsgDefinitions& extra) {
  for (const MsgDefinitions* table : {&extra, &standardDefinitions()}) {
    const auto it = table->find(short_name);
    if (it != table->end()) return &it->second;
  }
  return nullptr;
}

}  // namespace

bool ros2MsgDefinition(std::string_view type_name, const MsgDefinitions& extra, std::string* out,
                       std::string* error) {
  std::set<std::string> seen;
  std::function<bool(const std::string&, std::string*)> append = [&](const std::string& name,
                                                                     std::string* text) {
    const std::string short_name = shortName(name);
    const std::string* definition = findDefinition(short_name, extra);
    if (definition == nullptr) {
      *error = "no .msg definition for " + name;
      return false;
    }
    *text += *definition;
    const std::string package = short_name.substr(0, short_name.find('/'));
    for (const std::string& dep : dependencies(*definition, package)) {
      if (!seen.insert(shortName(dep)).second) continue;
      *text +=
          "\n================================================================================\nMSG:"
          " ";
      *text += dep;
      *text += "\n";
      if (!append(dep, text)) return false;
    }
    return true;
  };
  std::string text;
  if (!append(std::string(type_name), &text)) return false;
  *out = std::move(text);
  return true;
}

std::string ros2MsgDefinition(std::string_view type_name) {
  std::string text, error;
  return ros2MsgDefinition(type_name, MsgDefinitions{}, &text, &error) ? text : std::string();
}

}  // namespace deepnav::ros
