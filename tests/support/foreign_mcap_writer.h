#pragma once
// Test helper: a ROS 2 recording as `ros2 bag record -s mcap` writes it (ros2msg schemas, CDR messages),
// written with deepnav's own MCAP writer, for the foreign-recording tests.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "drivers/cdr/ros2msg_definitions.h"
#include "drivers/cdr/ros_msg_codec.h"
#include "drivers/mcap/writer.h"

namespace deepnav::testing {

class ForeignMcapWriter {
 public:
  explicit ForeignMcapWriter(const std::string& path) {
    mcap::WriterOptions o;
    o.library = "foreign test writer";
    std::string error;
    EXPECT_TRUE(writer_.open(path, o, &error)) << error;
  }

  // A message of a standard type on `topic` (its channel made at the first message).
  template <typename Msg>
  void write(const std::string& topic, const Msg& m, std::int64_t log_time_ns) {
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(ros::encode(m, &bytes));
    writeRaw(topic, std::string(Msg::kTypeName), ros::ros2MsgDefinition(Msg::kTypeName), "ros2msg", "cdr", bytes,
             log_time_ns);
  }

  // Any bytes on a channel of the given type and encodings.
  void writeRaw(const std::string& topic, const std::string& type, const std::string& schema_text,
                const std::string& schema_encoding, const std::string& message_encoding,
                const std::vector<std::uint8_t>& bytes, std::int64_t log_time_ns) {
    auto it = channels_.find(topic);
    if (it == channels_.end()) {
      const std::uint16_t schema = writer_.addSchema(type, schema_encoding, schema_text);
      it = channels_.emplace(topic, writer_.addChannel(schema, topic, message_encoding)).first;
    }
    EXPECT_TRUE(writer_.write(it->second, sequence_++, static_cast<std::uint64_t>(log_time_ns),
                              static_cast<std::uint64_t>(log_time_ns), bytes.data(), bytes.size()));
  }

  void close() {
    std::string error;
    EXPECT_TRUE(writer_.close(&error)) << error;
  }

 private:
  mcap::Writer writer_;
  std::map<std::string, std::uint16_t> channels_;
  std::uint32_t sequence_ = 0;
};

}  // namespace deepnav::testing
