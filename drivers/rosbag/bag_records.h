#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "drivers/rosbag/bag_format.h"
#include "drivers/rosbag/record_header.h"

// The fields of each record type (Bags/Format/2.0, "Op codes" and the record sections), read from a
// parsed header and the record's data. Each returns false with *what naming the missing or
// malformed field.
namespace deepnav::rosbag {

struct BagHeaderFields {
  uint64_t index_pos = 0;  // file offset of the first record after the chunk section; 0 = unclosed
  uint32_t conn_count = 0;
  uint32_t chunk_count = 0;
};

struct ChunkHeaderFields {
  std::string compression;  // "none", "bz2", "lz4"
  uint32_t size = 0;        // uncompressed bytes
};

bool parseBagHeader(const RecordHeader& header, BagHeaderFields* fields, std::string* what);
bool parseChunkHeader(const RecordHeader& header, ChunkHeaderFields* fields, std::string* what);
// Header: conn, topic. Data: a header-formatted field list with topic, type, md5sum,
// message_definition (callerid, latching optional).
bool parseConnection(const RecordHeader& header, const uint8_t* data, size_t size,
                     Connection* connection, std::string* what);
// Header: ver (1), chunk_pos, start_time, end_time, count. Data: count x (conn u32, count u32).
bool parseChunkInfo(const RecordHeader& header, const uint8_t* data, size_t size, ChunkRef* chunk,
                    std::string* what);
// Header: conn, time.
bool parseMessageData(const RecordHeader& header, uint32_t* conn, int64_t* time_ns,
                      std::string* what);

}  // namespace deepnav::rosbag
