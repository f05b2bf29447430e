#pragma once
#include <cstddef>
#include <cstdint>

#include "drivers/cdr/ros_msgs.h"

// ROS 1 serialization of the standard messages deepnav reads, into the structs of
// drivers/cdr/ros_msgs.h (the same structs the ROS 2 CDR codec fills). ROS 1 serializes
// little-endian and packed (no alignment); strings and variable arrays have a uint32 length before
// them, fixed arrays do not; time is uint32 sec, uint32 nsec; std_msgs/Header starts with a
// uint32 seq, which the structs do not keep.
// Each decoder reads exactly `size` bytes: false on a message too short, one with bytes left over,
// a length running past the end, nsec >= 1e9 or sec beyond int32 (the structs' Time).
namespace deepnav::rosbag {

bool decodeRos1(const uint8_t* data, size_t size, ros::Image* msg);
bool decodeRos1(const uint8_t* data, size_t size, ros::CompressedImage* msg);
bool decodeRos1(const uint8_t* data, size_t size, ros::Imu* msg);
bool decodeRos1(const uint8_t* data, size_t size, ros::FluidPressure* msg);
bool decodeRos1(const uint8_t* data, size_t size, ros::TwistStamped* msg);
bool decodeRos1(const uint8_t* data, size_t size, ros::TwistWithCovarianceStamped* msg);
bool decodeRos1(const uint8_t* data, size_t size, ros::MagneticField* msg);

}  // namespace deepnav::rosbag
