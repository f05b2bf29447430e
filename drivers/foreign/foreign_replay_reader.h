#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "drivers/cdr/ros_msgs.h"
#include "drivers/foreign/foreign_message.h"
#include "drivers/foreign/stereo_pairing.h"
#include "drivers/foreign/topic_map.h"
#include "drivers/replay/replay_event_source.h"

namespace deepnav::foreign {

// What the conversions take from the vehicle's setup (the board after the topic map's mountings).
struct ForeignVehicle {
  Eigen::Quaterniond q_robot_imu = Eigen::Quaterniond::Identity();  // ekf.imu_rotation_deg
  int width_px = 0;   // camera.width_px, camera.height_px: the images must have this size
  int height_px = 0;
  int channels = 1;   // camera.channels: images are converted to grey (1) or BGR (3)
  TimeUs pair_tolerance_us = 10'000;  // camera.pair_tolerance_ms, unless the map gives stereo.pair_tolerance_ms
};

// Per-topic counts of a converted recording (for the summary's warnings and the tests).
struct ForeignTopicCounts {
  std::uint64_t messages = 0;
  std::uint64_t samples = 0;        // loop inputs (or images) made from them
  std::uint64_t undecodable = 0;    // bytes that do not hold the type
  // Per sensor of the topic: messages that gave it no sample (e.g. an Imu without orientation asked for an
  // attitude; a compass reading without a recent attitude to level it).
  std::array<std::uint64_t, static_cast<std::size_t>(ForeignSensor::kCount)> without_value{};
};

// A ROS 1 bag or ROS 2 MCAP seen through a topic map as a stream of the loop's inputs and stereo pairs
// (the bench replay's event source). Events come in the container's log-time order; each sample carries
// its topic's time (header stamp or log time, TopicMapping::stamp). A topic of the map missing from the
// recording or of a type its sensor does not read, an encoding that cannot be decoded and a stamp going
// back beyond the topic's tolerance are errors naming the file and the topic.
class ForeignReplayReader : public ReplayEventSource {
 public:
  bool open(const std::string& path, const TopicMap& map, std::string* error);
  // Before forEach: the setup's mountings and camera (open() checked the topics without them).
  void setVehicle(const ForeignVehicle& vehicle);

  bool hasSolutions() const override { return false; }
  bool forEach(bool log_time_order, const Callback& callback, std::string* error) override;
  const std::map<std::string, std::string>* metadata(const std::string&) const override { return nullptr; }
  bool truncated() const override { return false; }
  const std::vector<std::string>& warnings() const override { return warnings_; }
  const ReplayReadStats& stats() const override { return stats_; }

  const ForeignTopicCounts* counts(const std::string& topic) const;
  std::uint64_t stereoPairs() const { return pairing_.pairs(); }

 private:
  enum class MsgKind { kImu, kTwistWithCovariance, kTwist, kPressure, kMagneticField, kImage, kCompressedImage, kOther };
  struct TopicState {
    const TopicMapping* map = nullptr;
    MsgKind kind = MsgKind::kOther;
    std::string type;
    bool any = false;
    TimeUs latest_us = 0;
    ForeignTopicCounts counts;
  };

  bool checkTopic(const TopicMapping& mapping, std::string* error);
  bool handle(const ForeignMessage& m, const Callback& callback, bool* stop, std::string* error);
  bool sampleTime(TopicState& s, const ForeignMessage& m, const ros::Time& stamp, TimeUs* t_us, std::string* error);
  bool emit(const InputSample& sample, const Callback& callback);
  bool handleImu(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop, std::string* error);
  bool handleDvl(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop, std::string* error);
  bool handleDepth(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop, std::string* error);
  bool handleCompass(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop, std::string* error);
  bool handleImage(TopicState& s, const ForeignMessage& m, const Callback& cb, bool* stop, std::string* error);
  bool undecodable(TopicState& s);
  std::string where(const TopicState& s) const;
  void summarise();

  std::string path_;
  TopicMap map_;
  std::unique_ptr<ForeignContainer> container_;
  ForeignVehicle vehicle_;
  std::unordered_map<std::string, TopicState> topics_;
  StereoPairing pairing_;
  StereoFrame frame_;
  cv::Mat image_;
  bool have_attitude_ = false;
  AttitudeSample attitude_;  // the newest attitude delivered (compass tilt compensation)
  ReplayReadStats stats_;
  std::vector<std::string> warnings_;
};

}  // namespace deepnav::foreign
