#include "drivers/rosbag/bag_records.h"

namespace deepnav::rosbag {

bool parseBagHeader(const RecordHeader& header, BagHeaderFields* fields, std::string* what) {
  return header.u64("index_pos", &fields->index_pos, what) &&
         header.u32("conn_count", &fields->conn_count, what) &&
         header.u32("chunk_count", &fields->chunk_count, what);
}

bool parseChunkHeader(const RecordHeader& header, ChunkHeaderFields* fields, std::string* what) {
  return header.string("compression", &fields->compression, what) &&
         header.u32("size", &fields->size, what);
}

bool parseConnection(const RecordHeader& header, const uint8_t* data, size_t size,
                     Connection* connection, std::string* what) {
  if (!header.u32("conn", &connection->id, what) ||
      !header.string("topic", &connection->topic, what)) {
    return false;
  }
  RecordHeader body;
  if (!body.parse(data, size, what)) {
    *what = "connection data: " + *what;
    return false;
  }
  if (!body.string("type", &connection->type, what) ||
      !body.string("md5sum", &connection->md5sum, what)) {
    *what = "connection data: " + *what;
    return false;
  }
  // Optional in practice: rosbag always writes it, other writers sometimes leave it out.
  if (!body.string("message_definition", &connection->message_definition, what)) {
    connection->message_definition.clear();
  }
  what->clear();
  return true;
}

bool parseChunkInfo(const RecordHeader& header, const uint8_t* data, size_t size, ChunkRef* chunk,
                    std::string* what) {
  uint32_t version = 0;
  uint32_t count = 0;
  if (!header.u32("ver", &version, what)) return false;
  if (version != 1) {
    *what = "header field 'ver' is " + std::to_string(version) + ", this reader knows 1";
    return false;
  }
  if (!header.u64("chunk_pos", &chunk->pos, what) ||
      !header.timeNs("start_time", &chunk->start_ns, what) ||
      !header.timeNs("end_time", &chunk->end_ns, what) || !header.u32("count", &count, what)) {
    return false;
  }
  if (uint64_t(count) * 8 != size) {
    *what = "header field 'count' says " + std::to_string(count) + " connections (" +
            std::to_string(uint64_t(count) * 8) + " bytes), the data has " + std::to_string(size);
    return false;
  }
  chunk->messages_per_connection.clear();
  for (uint32_t i = 0; i < count; ++i) {
    const uint8_t* p = data + 8 * size_t(i);
    const uint32_t conn = uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 |
                          uint32_t(p[3]) << 24;
    const uint32_t n = uint32_t(p[4]) | uint32_t(p[5]) << 8 | uint32_t(p[6]) << 16 |
                       uint32_t(p[7]) << 24;
    chunk->messages_per_connection[conn] += n;
  }
  return true;
}

bool parseMessageData(const RecordHeader& header, uint32_t* conn, int64_t* time_ns,
                      std::string* what) {
  return header.u32("conn", conn, what) && header.timeNs("time", time_ns, what);
}

}  // namespace deepnav::rosbag
