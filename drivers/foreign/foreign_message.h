#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

// Recordings other tools wrote (ROS 1 bags, ROS 2 MCAP files), seen as one stream of serialized
// messages. A container reader (drivers/rosbag for ROS 1, drivers/foreign for ROS 2 MCAP) yields
// ForeignMessage; drivers/foreign decodes the standard message types into the structs of
// drivers/cdr/ros_msgs.h (the same structs for both serializations) and converts them, through a topic
// map, into the samples the nav loop consumes.
namespace deepnav::foreign {

enum class Serialization : std::uint8_t {
  kRos1,  // ROS 1: little-endian, packed, uint32 length before strings and variable arrays
  kCdr,   // ROS 2: XCDR1 with the 4-byte encapsulation header
};

// One message, valid during the callback only.
struct ForeignMessage {
  std::string_view topic;
  std::string_view type;  // as the file names it: "sensor_msgs/Imu" (ROS 1), "sensor_msgs/msg/Imu" (ROS 2)
  Serialization serialization = Serialization::kCdr;
  std::int64_t log_time_ns = 0;  // when the recorder received it (the container's time), ns since epoch
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

struct ForeignTopic {
  std::string name;
  std::string type;
  Serialization serialization = Serialization::kCdr;
  std::uint64_t messages = 0;  // from the file's index or summary; 0 when it has none
  // Why its messages cannot be decoded (e.g. an MCAP channel in another encoding than cdr/ros2msg);
  // empty when they can. forEach() skips such a topic's messages.
  std::string unsupported;
};

// A foreign recording opened for reading. Implementations check the container (magic, version,
// record lengths, compression) in open and name the file and the offending record on error.
class ForeignContainer {
 public:
  using Callback = std::function<bool(const ForeignMessage&)>;  // return false to stop
  virtual ~ForeignContainer() = default;
  virtual const std::vector<ForeignTopic>& topics() const = 0;
  // Every message in log-time order (ties in file order). False with *error on a damaged container;
  // messages already delivered stay delivered.
  virtual bool forEach(const Callback& callback, std::string* error) = 0;
};

}  // namespace deepnav::foreign
