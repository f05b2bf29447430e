#pragma once
#include <memory>
#include <string>

#include "drivers/foreign/foreign_message.h"

namespace deepnav::foreign {

// Opens a foreign recording, choosing the reader by the file's first bytes: the MCAP magic
// (0x89 "MCAP0\r\n": a ROS 2 recording, McapContainer) or "#ROSBAG V2.0\n" (a ROS 1 bag,
// rosbag::BagReader). nullptr with *error naming the file when it is neither or does not open.
std::unique_ptr<ForeignContainer> openForeignContainer(const std::string& path, std::string* error);

}  // namespace deepnav::foreign
