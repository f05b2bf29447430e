#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "drivers/foreign/foreign_message.h"
#include "drivers/mcap/reader.h"

namespace deepnav::foreign {

// A ROS 2 recording in MCAP (what `ros2 bag record -s mcap` writes, and deepnav's own recordings) as a
// ForeignContainer. Only channels with message encoding "cdr" and a "ros2msg" schema can be decoded; any
// other channel (JSON, protobuf, ros1msg...) is listed with ForeignTopic::unsupported naming its
// encodings, and its messages are skipped.
class McapContainer : public ForeignContainer {
 public:
  bool open(const std::string& path, std::string* error);
  const std::vector<ForeignTopic>& topics() const override { return topics_; }
  bool forEach(const Callback& callback, std::string* error) override;

 private:
  struct ChannelInfo {
    std::string topic;
    std::string type;
    bool supported = false;
  };
  mcap::Reader reader_;
  std::vector<ForeignTopic> topics_;
  std::map<std::uint16_t, ChannelInfo> channels_;
};

}  // namespace deepnav::foreign
