#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

// The MCAP records a deepnav program sees: what the Writer takes and the Reader exposes.
// Times are nanoseconds on the recording's clock (deepnav: the monotonic clock, t_us * 1000).
namespace deepnav::mcap {

struct Header {
  std::string profile;  // "ros2" for deepnav recordings
  std::string library;  // free text naming the writer
};

struct Schema {
  uint16_t id = 0;       // never 0 in a valid file
  std::string name;      // e.g. "sensor_msgs/msg/Imu"
  std::string encoding;  // e.g. "ros2msg"
  std::vector<uint8_t> data;
};

struct Channel {
  uint16_t id = 0;
  uint16_t schema_id = 0;  // 0: no schema
  std::string topic;
  std::string message_encoding;  // e.g. "cdr"
  std::map<std::string, std::string> metadata;
};

struct Statistics {
  uint64_t message_count = 0;
  uint16_t schema_count = 0;
  uint32_t channel_count = 0;
  uint32_t attachment_count = 0;
  uint32_t metadata_count = 0;
  uint32_t chunk_count = 0;
  uint64_t message_start_time_ns = 0;  // 0 when there are no messages
  uint64_t message_end_time_ns = 0;
  std::map<uint16_t, uint64_t> channel_message_counts;
};

// Where one chunk sits in the file (a Chunk Index record, or the same found by scanning).
struct ChunkInfo {
  uint64_t message_start_time_ns = 0;
  uint64_t message_end_time_ns = 0;
  uint64_t chunk_start_offset = 0;  // byte offset of the Chunk record's opcode
  uint64_t chunk_length = 0;        // whole record, opcode and length prefix included
  uint64_t message_index_length = 0;
  std::string compression;  // "", "zstd" or "lz4"
  uint64_t compressed_size = 0;
  uint64_t uncompressed_size = 0;
};

struct Metadata {
  std::string name;
  std::map<std::string, std::string> metadata;
};

// One message as handed to a read callback. `data` points into the reader's buffers and is
// valid only during the callback.
struct MessageView {
  uint16_t channel_id = 0;
  uint32_t sequence = 0;
  uint64_t log_time_ns = 0;
  uint64_t publish_time_ns = 0;
  const uint8_t* data = nullptr;
  size_t size = 0;
};

}  // namespace deepnav::mcap
