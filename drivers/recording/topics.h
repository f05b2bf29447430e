#pragma once
#include <cstddef>
#include <string_view>

namespace deepnav {

// Every topic of a deepnav recording. The table in topics.cpp gives each its name, its ROS 2 message
// type (schema, encoding "ros2msg"; messages "cdr") and the frame_id written in its header.
enum class Topic : int {
  kImu = 0,        // sensor_msgs/msg/Imu
  kDvl,            // geometry_msgs/msg/TwistWithCovarianceStamped (for viewers)
  kDvlBottomTrack, // deepnav_msgs/msg/DvlBottomTrack (the whole DvlSample; replay reads this one)
  kPressure,       // sensor_msgs/msg/FluidPressure (for viewers)
  kDepth,          // deepnav_msgs/msg/Depth (the whole DepthSample; replay reads this one)
  kHeading,        // deepnav_msgs/msg/Heading
  kAttitude,       // deepnav_msgs/msg/Attitude
  kVisionResult,   // deepnav_msgs/msg/VisionResult
  kStereoInfo,     // deepnav_msgs/msg/StereoInfo (precedes the two images of a pair)
  kLeftImage,      // sensor_msgs/msg/Image
  kRightImage,     // sensor_msgs/msg/Image
  kOdometry,       // nav_msgs/msg/Odometry (for viewers and ROS tools)
  kNavSolution,    // deepnav_msgs/msg/NavSolution (bit-exact output; ends a loop tick)
  kLoopStats,      // deepnav_msgs/msg/LoopStats
  kTruth,          // nav_msgs/msg/Odometry, simulator ground truth
  kFrameTruth,     // deepnav_msgs/msg/FrameTruth: true robot and camera poses, visible markers per stereo pair
  kTruthDepth,     // sensor_msgs/msg/Image 32FC1: true depth of the left image, m, 0 = no surface
  kTruthDisparity, // sensor_msgs/msg/Image 16UC1: true disparity of the left image, px * 128, 0 = no surface
  kFusion,         // deepnav_msgs/msg/FusionDiagnostic: one measurement's fusion (innovation, test ratio, why refused)
  kEstimatorStates,  // deepnav_msgs/msg/EstimatorStates: sensor-error estimates and sigmas (1 Hz, when the board estimates any)
  kCount
};

struct TopicInfo {
  std::string_view name;
  std::string_view type;      // "pkg/msg/Type"
  std::string_view frame_id;  // header.frame_id of its messages
};

const TopicInfo& topicInfo(Topic topic);
// Topic of a channel name, or Topic::kCount when deepnav does not know it.
Topic topicByName(std::string_view name);

// Full ros2msg schema text of a topic's type (standard or deepnav_msgs), with its dependencies.
std::string_view topicSchema(Topic topic);

constexpr std::size_t kTopicCount = static_cast<std::size_t>(Topic::kCount);

}  // namespace deepnav
