#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

// The ROS 1 bag format, version 2.0 (http://wiki.ros.org/Bags/Format/2.0): the magic line, the
// record op codes and the records the reader keeps once parsed. Every record is
// <header_len u32><header: name=value fields><data_len u32><data>, little-endian.
namespace deepnav::rosbag {

inline constexpr std::string_view kMagic = "#ROSBAG V2.0\n";
inline constexpr std::string_view kMagicPrefix = "#ROSBAG V";

enum class Op : uint8_t {
  kMessageData = 0x02,
  kBagHeader = 0x03,
  kIndexData = 0x04,
  kChunk = 0x05,
  kChunkInfo = 0x06,
  kConnection = 0x07,
};

// "message data record", ... for error messages.
std::string_view opName(uint8_t op);

// "<path>: byte <offset>: <what>", the one shape of every reader error.
std::string errorAt(const std::string& path, uint64_t offset, std::string_view what);

// A connection record: one publisher's topic with its type. Several connections may share a topic.
struct Connection {
  uint32_t id = 0;
  std::string topic;
  std::string type;       // "sensor_msgs/Imu"
  std::string md5sum;     // of the message definition, per the ROS md5 rule
  std::string message_definition;
  uint64_t offset = 0;    // where the record was found (file byte, or chunk byte), for errors
};

// A chunk of the chunk section, from its chunk info record (indexed bag) or from a scan.
struct ChunkRef {
  uint64_t pos = 0;        // file offset of the chunk record
  int64_t start_ns = 0;    // earliest message log time in the chunk
  int64_t end_ns = 0;      // latest
  std::map<uint32_t, uint32_t> messages_per_connection;
  // From the chunk record's header.
  std::string compression;
  uint32_t size = 0;         // uncompressed bytes
  uint64_t data_offset = 0;  // file offset of the (compressed) data
  uint64_t data_len = 0;     // bytes of data present in the file
  bool partial = false;      // cut short: only its leading records are read
};

// ROS 1 time (uint32 sec, uint32 nsec) as nanoseconds.
inline int64_t rosTimeNs(uint32_t sec, uint32_t nsec) {
  return int64_t(sec) * 1000000000LL + int64_t(nsec);
}

}  // namespace deepnav::rosbag
