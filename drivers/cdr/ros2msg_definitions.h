#pragma once
#include <map>
#include <string>
#include <string_view>

// Schema text for MCAP channels with the "ros2msg" schema encoding: the message's .msg
// definition, then each type it depends on, recursively, each preceded by a line of 80 '=' and
// a line "MSG: pkg/Type". The order and separators are those of rosbag2's
// LocalMessageDefinitionSource (dependencies of a definition in sorted order, depth first, each
// once), so our schemas read like the ones ros2 bag record writes. The .msg texts here carry the
// fields (and ROS default values) without the comments of the upstream files.
namespace deepnav::ros {

inline constexpr std::string_view kRos2MsgEncoding = "ros2msg";
inline constexpr std::string_view kCdrEncoding = "cdr";

// .msg texts of further types, keyed "pkg/Type" (e.g. "deepnav_msgs/NavSolution"), that may
// depend on each other and on the standard types this module knows.
using MsgDefinitions = std::map<std::string, std::string, std::less<>>;

// Full definition of `type_name` ("pkg/msg/Type" or "pkg/Type"). False, with *error naming the
// missing type, if it or a dependency is unknown.
bool ros2MsgDefinition(std::string_view type_name, const MsgDefinitions& extra, std::string* out,
                       std::string* error);

// Full definition of a standard type this module knows ("sensor_msgs/msg/Imu", ...); empty if
// unknown.
std::string ros2MsgDefinition(std::string_view type_name);

}  // namespace deepnav::ros
