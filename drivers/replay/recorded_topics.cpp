#include "drivers/replay/recorded_topics.h"

namespace deepnav {

bool RecordedTopics::open(const std::string& path, std::string* error) {
  if (!reader_.open(path, error)) return false;
  topic_of_channel_.clear();
  counts_.fill(0);
  const auto& message_counts = reader_.statistics().channel_message_counts;
  for (const auto& [id, channel] : reader_.channels()) {
    const Topic topic = topicByName(channel.topic);
    topic_of_channel_[id] = topic;
    if (topic == Topic::kCount) continue;
    const auto it = message_counts.find(id);
    if (it != message_counts.end()) counts_[static_cast<std::size_t>(topic)] += it->second;
  }
  return true;
}

const std::map<std::string, std::string>* RecordedTopics::metadata(const std::string& name) const {
  for (const auto& m : reader_.metadata()) {
    if (m.name == name) return &m.metadata;
  }
  return nullptr;
}

}  // namespace deepnav
