#pragma once
// Shared by the rosbag_*_test.cpp files: sample messages of every type, reading a bag back whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "drivers/cdr/ros_msgs.h"
#include "drivers/rosbag/bag_reader.h"
#include "tests/support/temp_path.h"

namespace deepnav::rosbag::testing_util {

inline std::vector<uint8_t> readBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<uint8_t>(std::istreambuf_iterator<char>(in), {});
}

inline void writeBytes(const std::string& path, const uint8_t* data, size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
}

struct Delivered {
  std::string topic;
  std::string type;
  int64_t log_time_ns = 0;
  std::vector<uint8_t> data;
};

// forEach into a list; *ok and *error as forEach returned them.
inline std::vector<Delivered> readAll(BagReader& reader, bool* ok, std::string* error) {
  std::vector<Delivered> out;
  *ok = reader.forEach(
      [&](const foreign::ForeignMessage& m) {
        EXPECT_EQ(m.serialization, foreign::Serialization::kRos1);
        out.push_back({std::string(m.topic), std::string(m.type), m.log_time_ns,
                       std::vector<uint8_t>(m.data, m.data + m.size)});
        return true;
      },
      error);
  return out;
}

inline ros::Header header(int32_t sec, uint32_t nanosec, const std::string& frame) {
  ros::Header h;
  h.stamp.sec = sec;
  h.stamp.nanosec = nanosec;
  h.frame_id = frame;
  return h;
}

// Messages whose every field differs from its neighbours and from the defaults, so a decoder that
// swaps or skips a field cannot pass.
inline ros::Imu sampleImu(int i) {
  ros::Imu m;
  m.header = header(1700000000 + i, 1000u * uint32_t(i) + 7u, "imu_link");
  m.orientation = {0.1 + i, 0.2, 0.3, 0.9};
  for (size_t k = 0; k < 9; ++k) {
    m.orientation_covariance[k] = 1.0 + double(k);
    m.angular_velocity_covariance[k] = 10.0 + double(k);
    m.linear_acceleration_covariance[k] = 100.0 + double(k);
  }
  m.angular_velocity = {0.01 * i, -0.02, 0.03};
  m.linear_acceleration = {0.4, -0.5, 9.81 + i};
  return m;
}

inline ros::Image sampleImage(int i) {
  ros::Image m;
  m.header = header(1700000100 + i, 5u, "cam0");
  m.height = 3;
  m.width = 4;
  m.encoding = "mono8";
  m.is_bigendian = 1;
  m.step = 4;
  for (int k = 0; k < 12; ++k) m.data.push_back(uint8_t(k * 17 + i));
  return m;
}

inline ros::CompressedImage sampleCompressedImage(int i) {
  ros::CompressedImage m;
  m.header = header(1700000200 + i, 6u, "cam1");
  m.format = "jpeg";
  m.data = {0xFF, 0xD8, uint8_t(i), 0x00, 0xFF, 0xD9};
  return m;
}

inline ros::FluidPressure sampleFluidPressure(int i) {
  ros::FluidPressure m;
  m.header = header(1700000300 + i, 8u, "depth");
  m.fluid_pressure = 101325.0 + 1000.0 * i;
  m.variance = 4.5;
  return m;
}

inline ros::TwistStamped sampleTwistStamped(int i) {
  ros::TwistStamped m;
  m.header = header(1700000400 + i, 9u, "dvl");
  m.twist.linear = {0.5 + i, -0.25, 0.125};
  m.twist.angular = {0.001, 0.002, 0.003 * i};
  return m;
}

inline ros::TwistWithCovarianceStamped sampleTwistWithCovariance(int i) {
  ros::TwistWithCovarianceStamped m;
  m.header = header(1700000500 + i, 10u, "dvl");
  m.twist.twist.linear = {0.7, 0.8 + i, -0.9};
  m.twist.twist.angular = {-0.1, 0.2, -0.3};
  for (size_t k = 0; k < 36; ++k) m.twist.covariance[k] = 0.5 * double(k) + i;
  return m;
}

inline ros::MagneticField sampleMagneticField(int i) {
  ros::MagneticField m;
  m.header = header(1700000600 + i, 11u, "mag");
  m.magnetic_field = {2.1e-5, -0.4e-5 * i, 4.3e-5};
  for (size_t k = 0; k < 9; ++k) m.magnetic_field_covariance[k] = 1e-12 * double(k + 1);
  return m;
}

}  // namespace deepnav::rosbag::testing_util
