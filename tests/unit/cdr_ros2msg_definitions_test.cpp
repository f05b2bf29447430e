// ros2msg schema texts: the layout rosbag2 writes (definition, then dependencies in sorted
// order, depth first, each once, behind an 80-'=' line and "MSG: pkg/Type").
#include <gtest/gtest.h>

#include <string>

#include "drivers/cdr/ros2msg_definitions.h"
#include "drivers/cdr/ros_msgs.h"

namespace deepnav::ros {
namespace {

const std::string kRule(80, '=');

std::string section(const std::string& type, const std::string& text) {
  return "\n" + kRule + "\nMSG: " + type + "\n" + text;
}

size_t count(const std::string& haystack, const std::string& needle) {
  size_t n = 0;
  for (size_t at = haystack.find(needle); at != std::string::npos;
       at = haystack.find(needle, at + 1))
    ++n;
  return n;
}

TEST(CdrRos2Msg, ImuDefinitionIsExactlyWhatRosbag2Writes) {
  const std::string header = "builtin_interfaces/Time stamp\nstring frame_id\n";
  const std::string time = "int32 sec\nuint32 nanosec\n";
  const std::string expected =
      "std_msgs/Header header\n\n"
      "geometry_msgs/Quaternion orientation\nfloat64[9] orientation_covariance\n\n"
      "geometry_msgs/Vector3 angular_velocity\nfloat64[9] angular_velocity_covariance\n\n"
      "geometry_msgs/Vector3 linear_acceleration\nfloat64[9] linear_acceleration_covariance\n" +
      section("geometry_msgs/Quaternion", "float64 x 0\nfloat64 y 0\nfloat64 z 0\nfloat64 w 1\n") +
      section("geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n") +
      section("std_msgs/Header", header) + section("builtin_interfaces/Time", time);
  EXPECT_EQ(ros2MsgDefinition(Imu::kTypeName), expected);
}

TEST(CdrRos2Msg, EveryStandardTypeResolvesWithEachDependencyOnce) {
  const std::string odometry = ros2MsgDefinition(Odometry::kTypeName);
  for (const char* dep : {"MSG: std_msgs/Header\n", "MSG: builtin_interfaces/Time\n",
                          "MSG: geometry_msgs/PoseWithCovariance\n", "MSG: geometry_msgs/Pose\n",
                          "MSG: geometry_msgs/Point\n", "MSG: geometry_msgs/Quaternion\n",
                          "MSG: geometry_msgs/TwistWithCovariance\n", "MSG: geometry_msgs/Twist\n",
                          "MSG: geometry_msgs/Vector3\n"}) {
    EXPECT_EQ(count(odometry, dep), 1u) << dep;
  }
  EXPECT_EQ(count(odometry, kRule + "\n"), 9u);
  EXPECT_EQ(odometry.rfind("std_msgs/Header header\nstring child_frame_id\n", 0), 0u);

  for (const std::string_view type : {Image::kTypeName, FluidPressure::kTypeName,
                                      TwistWithCovarianceStamped::kTypeName, Header::kTypeName}) {
    const std::string text = ros2MsgDefinition(type);
    EXPECT_FALSE(text.empty()) << type;
  }
  EXPECT_EQ(count(ros2MsgDefinition(Image::kTypeName), "MSG: "), 2u);
  EXPECT_EQ(count(ros2MsgDefinition(TwistWithCovarianceStamped::kTypeName), "MSG: "), 5u);
  EXPECT_TRUE(ros2MsgDefinition("sensor_msgs/msg/NavSatFix").empty());
}

TEST(CdrRos2Msg, ProjectMessagesResolveAgainstStandardAndExtraTypes) {
  const MsgDefinitions extra = {
      {"deepnav_msgs/NavSolution", "std_msgs/Header header\nNavStatus status\nfloat64 depth_m\n"},
      {"deepnav_msgs/NavStatus", "uint8 MODE_DEAD_RECKONING=1\nuint8 mode\n"},
  };
  std::string text, error;
  ASSERT_TRUE(ros2MsgDefinition("deepnav_msgs/msg/NavSolution", extra, &text, &error)) << error;
  EXPECT_EQ(text,
            "std_msgs/Header header\nNavStatus status\nfloat64 depth_m\n" +
                section("deepnav_msgs/NavStatus", "uint8 MODE_DEAD_RECKONING=1\nuint8 mode\n") +
                section("std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n") +
                section("builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"));

  const MsgDefinitions missing = {{"deepnav_msgs/Broken", "deepnav_msgs/Nowhere x\n"}};
  EXPECT_FALSE(ros2MsgDefinition("deepnav_msgs/Broken", missing, &text, &error));
  EXPECT_NE(error.find("deepnav_msgs/Nowhere"), std::string::npos) << error;
}

}  // namespace
}  // namespace deepnav::ros
