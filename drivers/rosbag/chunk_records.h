#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "drivers/rosbag/bag_format.h"

// The records inside one decompressed chunk: connection records (written the first time a
// connection appears) and message data records. Other op codes inside a chunk are skipped.
namespace deepnav::rosbag {

struct MessageEntry {
  int64_t time_ns = 0;
  uint32_t conn = 0;
  uint32_t order = 0;        // position among the chunk's messages: file order
  uint64_t data_offset = 0;  // serialized message within the chunk bytes
  uint32_t data_size = 0;
};

struct ChunkContent {
  std::vector<Connection> connections;
  std::vector<MessageEntry> messages;  // file order
  uint64_t complete_bytes = 0;         // bytes of whole records from the start
};

// Walks the records of data[0, size). With `complete`, every byte must belong to a whole record;
// without (a chunk cut short), the walk stops at the first record cut off. False with *what and
// *what_offset (byte within the chunk) on a malformed record.
bool parseChunkRecords(const uint8_t* data, size_t size, bool complete, ChunkContent* content,
                       std::string* what, uint64_t* what_offset);

}  // namespace deepnav::rosbag
