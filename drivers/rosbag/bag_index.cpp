#include "drivers/rosbag/bag_index.h"

#include "drivers/rosbag/chunk_loading.h"

namespace deepnav::rosbag {
namespace {

bool readIndexRecords(BagFile& file, uint64_t index_pos, BagIndex* index, std::string* why) {
  std::vector<uint8_t> data;
  uint64_t pos = index_pos;
  for (;;) {
    RecordFrame frame;
    RecordHeader header;
    std::string what;
    const ReadStatus status = file.readRecord(pos, file.size(), &frame, &header, &what);
    if (status == ReadStatus::kEnd) return true;
    uint8_t op = 0;
    if (status != ReadStatus::kOk || !header.op(&op, &what)) {
      *why = errorAt(file.path(), pos,
                     "index section record " + (what.empty() ? "cut short" : what));
      return false;
    }
    if (op == uint8_t(Op::kConnection) || op == uint8_t(Op::kChunkInfo)) {
      if (!file.readData(frame, frame.data_len, &data)) {
        *why = errorAt(file.path(), frame.data_offset, "index section: read error");
        return false;
      }
    }
    if (op == uint8_t(Op::kConnection)) {
      Connection c;
      if (!parseConnection(header, data.data(), data.size(), &c, &what) ||
          !addConnection(file.path(), std::move(c), index, &what)) {
        *why = errorAt(file.path(), pos, "connection record: " + what);
        return false;
      }
    } else if (op == uint8_t(Op::kChunkInfo)) {
      ChunkRef chunk;
      if (!parseChunkInfo(header, data.data(), data.size(), &chunk, &what)) {
        *why = errorAt(file.path(), pos, "chunk info record: " + what);
        return false;
      }
      index->chunks.push_back(std::move(chunk));
    }
    pos = frame.end();
  }
}

}  // namespace

bool addConnection(const std::string& path, Connection connection, BagIndex* index,
                   std::string* error) {
  const auto it = index->connections.find(connection.id);
  if (it == index->connections.end()) {
    index->connections.emplace(connection.id, std::move(connection));
    return true;
  }
  if (it->second.topic != connection.topic || it->second.type != connection.type) {
    *error = errorAt(path, connection.offset,
                     "connection " + std::to_string(connection.id) + " is '" + connection.topic +
                         "' (" + connection.type + ") here and '" + it->second.topic + "' (" +
                         it->second.type + ") at byte " + std::to_string(it->second.offset));
    return false;
  }
  return true;
}

bool readIndex(BagFile& file, const BagHeaderFields& header, uint64_t chunks_start,
               BagIndex* index, std::string* why, std::string* error) {
  if (!readIndexRecords(file, header.index_pos, index, why)) return false;
  if (index->connections.size() != header.conn_count ||
      index->chunks.size() != header.chunk_count) {
    *why = errorAt(file.path(), header.index_pos,
                   "the index holds " + std::to_string(index->connections.size()) +
                       " connections and " + std::to_string(index->chunks.size()) +
                       " chunk infos, the bag header says " + std::to_string(header.conn_count) +
                       " and " + std::to_string(header.chunk_count));
    return false;
  }
  for (ChunkRef& chunk : index->chunks) {
    if (chunk.pos < chunks_start || chunk.pos >= header.index_pos) {
      *why = errorAt(file.path(), header.index_pos,
                     "a chunk info record gives chunk_pos " + std::to_string(chunk.pos) +
                         ", outside the chunk section");
      return false;
    }
    if (!locateChunk(file, chunk.pos, header.index_pos, &chunk, error)) return false;
    if (chunk.partial) {
      *error = errorAt(file.path(), chunk.pos,
                       "chunk record: its data runs past the index section at byte " +
                           std::to_string(header.index_pos));
      return false;
    }
  }
  return true;
}

}  // namespace deepnav::rosbag
