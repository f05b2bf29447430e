#pragma once
#include <string_view>

#include "drivers/cdr/ros_msgs.h"
#include "drivers/foreign/foreign_message.h"

// One foreign message into the ROS message struct of its type, whichever serialization carried it:
// CDR (ROS 2, drivers/cdr/ros_msg_codec) or ROS 1 (drivers/rosbag/ros1_msg_codec). False when the bytes
// do not hold that message (short, overlong strings, another type). The caller matches the type first
// (sameRosType).
namespace deepnav::foreign {

bool decodeForeign(const ForeignMessage& m, ros::Imu* out);
bool decodeForeign(const ForeignMessage& m, ros::Image* out);
bool decodeForeign(const ForeignMessage& m, ros::CompressedImage* out);
bool decodeForeign(const ForeignMessage& m, ros::FluidPressure* out);
bool decodeForeign(const ForeignMessage& m, ros::TwistStamped* out);
bool decodeForeign(const ForeignMessage& m, ros::TwistWithCovarianceStamped* out);
bool decodeForeign(const ForeignMessage& m, ros::MagneticField* out);

// True when a type as a file names it ("sensor_msgs/Imu" in ROS 1, "sensor_msgs/msg/Imu" in ROS 2) is
// the ROS 2 type `ros2_name` ("sensor_msgs/msg/Imu").
bool sameRosType(std::string_view file_type, std::string_view ros2_name);

}  // namespace deepnav::foreign
