#include "drivers/foreign/mcap_container.h"

#include "drivers/cdr/ros2msg_definitions.h"

namespace deepnav::foreign {
namespace {

// Why a channel cannot be decoded as ROS 2 CDR, or "" when it can.
std::string unsupportedReason(const mcap::Channel& channel, const mcap::Schema* schema) {
  if (channel.message_encoding != ros::kCdrEncoding) {
    return "message encoding '" + channel.message_encoding + "' (only cdr is read)";
  }
  if (schema == nullptr) return "no schema (a ros2msg schema naming the type is needed)";
  if (schema->encoding != ros::kRos2MsgEncoding) {
    return "schema encoding '" + schema->encoding + "' (only ros2msg is read)";
  }
  return {};
}

}  // namespace

bool McapContainer::open(const std::string& path, std::string* error) {
  if (!reader_.open(path, error)) return false;
  topics_.clear();
  channels_.clear();
  // Topics in channel-id order; two channels on one topic (a re-advertised publisher) are one topic.
  std::map<std::string, std::size_t> topic_index;
  for (const auto& [id, channel] : reader_.channels()) {
    const mcap::Schema* schema = channel.schema_id != 0 ? reader_.schema(channel.schema_id) : nullptr;
    ChannelInfo info;
    info.topic = channel.topic;
    info.type = schema != nullptr ? schema->name : std::string();
    const std::string reason = unsupportedReason(channel, schema);
    info.supported = reason.empty();
    const auto counts = reader_.statistics().channel_message_counts.find(id);
    const std::uint64_t messages = counts == reader_.statistics().channel_message_counts.end() ? 0 : counts->second;
    const auto [it, added] = topic_index.emplace(channel.topic, topics_.size());
    if (added) {
      topics_.push_back({channel.topic, info.type, Serialization::kCdr, messages, reason});
    } else {
      ForeignTopic& t = topics_[it->second];
      t.messages += messages;
      if (t.type != info.type) t.unsupported = "two channels with different types (" + t.type + ", " + info.type + ")";
      if (t.unsupported.empty()) t.unsupported = reason;
    }
    channels_[id] = std::move(info);
  }
  return true;
}

bool McapContainer::forEach(const Callback& callback, std::string* error) {
  bool stopped = false;
  const bool ok = reader_.readAllInLogTimeOrder([&](const mcap::MessageView& m) {
    if (stopped) return;
    const auto it = channels_.find(m.channel_id);
    if (it == channels_.end() || !it->second.supported) return;
    ForeignMessage message;
    message.topic = it->second.topic;
    message.type = it->second.type;
    message.serialization = Serialization::kCdr;
    message.log_time_ns = static_cast<std::int64_t>(m.log_time_ns);
    message.data = m.data;
    message.size = m.size;
    if (!callback(message)) stopped = true;
  });
  if (!ok && error) *error = reader_.error();
  return ok;
}

}  // namespace deepnav::foreign
