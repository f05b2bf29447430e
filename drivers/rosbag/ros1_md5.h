#pragma once
#include <string>
#include <string_view>

// The md5sum ROS 1 gives each message type: a hash of its definition (comments and package names
// of embedded types removed, constants first, each embedded type replaced by its own md5), so two
// types with the same name but another layout have another md5
// (http://wiki.ros.org/ROS/Technical%20Overview#Message_serialization_and_msg_MD5_sums).
// The values for the types deepnav reads were computed by that rule from the .msg files of
// common_msgs (std_msgs/Header = md5("uint32 seq\ntime stamp\nstring frame_id") =
// 2176decaecbce78abc3b96ef049fabed, ...; tests/unit/rosbag_md5_test.cpp recomputes them) and are
// the ones `rosbag info` prints for these types.
namespace deepnav::rosbag {

// The standard md5sum of a ROS 1 type ("sensor_msgs/Imu"), or empty when deepnav does not decode
// that type.
std::string_view standardMd5(std::string_view ros1_type);

// False with *error naming the topic when `type` is one deepnav decodes and `md5sum` is not its
// standard one (a type of the same name with another layout, which decoding would misread).
bool checkLayout(std::string_view topic, std::string_view type, std::string_view md5sum,
                 std::string* error);

}  // namespace deepnav::rosbag
