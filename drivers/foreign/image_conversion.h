#pragma once
#include <string>

#include <opencv2/core.hpp>

#include "drivers/cdr/ros_msgs.h"

// ROS images into the 8-bit grey (channels 1) or BGR (channels 3) cv::Mat a StereoFrame holds.
// sensor_msgs/Image: mono8, 8UC1, bgr8, rgb8, bgra8, rgba8, 8UC3 (taken as bgr8), mono16 and 16UC1
// (either byte order; scaled to 8 bits by a right shift of mono16_bits - 8). Bayer, YUV, float and
// other encodings are refused by name. sensor_msgs/CompressedImage: JPEG and PNG (format naming
// "jpeg", "jpg" or "png", as image_transport writes it: "jpeg" or "bgr8; jpeg compressed bgr8"),
// decoded with cv::imdecode (a 16-bit PNG is brought to 8 bits as mono16 is); compressedDepth and
// anything else refused by name.
namespace deepnav::foreign {

bool imageFromRos(const ros::Image& m, int channels, int mono16_bits, cv::Mat* out, std::string* error);
bool imageFromRos(const ros::CompressedImage& m, int channels, int mono16_bits, cv::Mat* out, std::string* error);

}  // namespace deepnav::foreign
