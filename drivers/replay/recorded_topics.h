#pragma once
#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "drivers/mcap/reader.h"
#include "drivers/recording/topics.h"

namespace deepnav {

// A deepnav recording opened for reading: its channels resolved to the topics of topics.h and its
// messages counted per topic (from the statistics, or the scan of a file cut off). What every
// reader of our recordings (RecordingReader, TruthFrameReader) starts from.
class RecordedTopics {
 public:
  bool open(const std::string& path, std::string* error);

  // Topic::kCount for a channel whose topic is not one of ours.
  Topic topicOf(std::uint16_t channel_id) const {
    const auto it = topic_of_channel_.find(channel_id);
    return it == topic_of_channel_.end() ? Topic::kCount : it->second;
  }
  std::uint64_t count(Topic topic) const { return counts_[static_cast<std::size_t>(topic)]; }
  // The Metadata record `name`, null when absent.
  const std::map<std::string, std::string>* metadata(const std::string& name) const;

  mcap::Reader& reader() { return reader_; }
  const mcap::Reader& reader() const { return reader_; }

 private:
  mcap::Reader reader_;
  std::map<std::uint16_t, Topic> topic_of_channel_;
  std::array<std::uint64_t, kTopicCount> counts_{};
};

}  // namespace deepnav
