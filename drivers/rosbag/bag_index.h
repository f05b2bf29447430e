#pragma once
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "drivers/rosbag/bag_file.h"
#include "drivers/rosbag/bag_format.h"
#include "drivers/rosbag/bag_records.h"

// What the reader knows of a bag before reading messages: its connections and its chunks (with
// their time ranges and message counts per connection).
namespace deepnav::rosbag {

struct BagIndex {
  std::map<uint32_t, Connection> connections;
  std::vector<ChunkRef> chunks;  // file order
  bool scanned = false;          // built by scanning the chunk section, not from the index
  std::string notice;            // why the index was not used (scanned only)
  std::string loss;              // bytes that could not be read, as an error; empty when none
  uint64_t scan_end = 0;         // scanned only: the file offset up to which records were whole
};

// Adds a connection, once per id (the index repeats the chunks' connection records). False with
// *error when the same id names another topic or type.
bool addConnection(const std::string& path, Connection connection, BagIndex* index,
                   std::string* error);

// The index section of a closed bag: conn_count connection records then chunk_count chunk info
// records from header.index_pos to the end of the file, then each chunk's record header. False
// with *why when the index section is unusable (cut short, malformed, counts that disagree): the
// caller then scans the chunks. A chunk record the index points at that is malformed (unknown
// compression, ...) is a hard error: *error set, *why empty.
bool readIndex(BagFile& file, const BagHeaderFields& header, uint64_t chunks_start,
               BagIndex* index, std::string* why, std::string* error);

// A bag that was not closed (index_pos 0), or whose index is beyond the end of the file or
// damaged: walks the records from chunks_start to `limit`, decompressing each chunk to learn its
// connections, time range and counts. A record cut off at the end (the recorder stopped) ends the
// walk: the messages before it are kept and index->loss says what was lost. False with *error on
// a malformed record before the end.
bool scanChunks(BagFile& file, uint64_t chunks_start, uint64_t limit, BagIndex* index,
                std::string* error);

}  // namespace deepnav::rosbag
