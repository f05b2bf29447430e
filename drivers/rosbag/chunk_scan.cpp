// scanChunks (bag_index.h): reading a bag without its index, as `rosbag reindex` would.
#include <algorithm>
#include <limits>

#include "drivers/rosbag/bag_index.h"
#include "drivers/rosbag/chunk_loading.h"

namespace deepnav::rosbag {
namespace {

struct Scan {
  BagFile& file;
  uint64_t limit;
  BagIndex* index;
  ChunkDecompressor decompressor;
  std::vector<uint8_t> compressed;
  std::vector<uint8_t> bytes;
  ChunkContent content;
};

// Time range, counts and connections of a chunk from its records. A chunk without messages is
// dropped.
bool learnChunk(Scan* scan, ChunkRef chunk, std::string* error) {
  if (!loadChunk(scan->file, chunk, &scan->decompressor, &scan->compressed, &scan->bytes,
                 &scan->content, error)) {
    return false;
  }
  for (Connection& c : scan->content.connections) {
    c.offset += chunk.pos;  // nearest file byte: the chunk's
    if (!addConnection(scan->file.path(), std::move(c), scan->index, error)) return false;
  }
  if (scan->content.messages.empty()) return true;
  chunk.start_ns = std::numeric_limits<int64_t>::max();
  chunk.end_ns = std::numeric_limits<int64_t>::min();
  for (const MessageEntry& m : scan->content.messages) {
    chunk.start_ns = std::min(chunk.start_ns, m.time_ns);
    chunk.end_ns = std::max(chunk.end_ns, m.time_ns);
    ++chunk.messages_per_connection[m.conn];
  }
  scan->index->chunks.push_back(std::move(chunk));
  return true;
}

std::string cutShort(const BagFile& file, uint64_t pos, std::string_view what) {
  return errorAt(file.path(), pos,
                 std::string(what) + "; the bag ends at byte " + std::to_string(file.size()) +
                     " (recording interrupted?): the messages from here on are lost");
}

// A chunk record whose sizes are still rosbag's placeholders (0, 0): the recorder stopped while
// writing it, and its records follow the header up to the end of the file.
bool unfinishedChunk(Scan* scan, ChunkRef chunk, std::string* error) {
  const uint64_t present = scan->limit - chunk.data_offset;
  if (chunk.compression != "none") {
    scan->index->loss =
        cutShort(scan->file, chunk.pos,
                 "chunk record never finished by the recorder (sizes 0): its " +
                     std::to_string(present) + " " + chunk.compression + " bytes cannot be read");
    return true;
  }
  chunk.partial = true;
  chunk.data_len = present;
  chunk.size = uint32_t(std::min<uint64_t>(present, kMaxChunkBytes));
  if (!learnChunk(scan, chunk, error)) return false;
  if (scan->content.complete_bytes == present) {
    scan->index->notice = errorAt(scan->file.path(), chunk.pos,
                                  "last chunk never finished by the recorder (sizes 0); its " +
                                      std::to_string(scan->content.messages.size()) +
                                      " messages are whole and were read");
  } else {
    scan->index->loss = cutShort(scan->file, chunk.data_offset + scan->content.complete_bytes,
                                 "chunk record never finished by the recorder (sizes 0): read "
                                 "up to its first record cut short at byte " +
                                     std::to_string(scan->content.complete_bytes) +
                                     " of its data");
  }
  return true;
}

// Handles the chunk at `frame`; *stop when it was the last thing the file holds.
bool scanChunk(Scan* scan, const RecordFrame& frame, bool* stop, std::string* error) {
  ChunkRef chunk;
  if (!locateChunk(scan->file, frame.offset, scan->limit, &chunk, error)) return false;
  if (chunk.size == 0 && frame.data_len == 0 && frame.end() < scan->limit) {
    *stop = true;
    return unfinishedChunk(scan, std::move(chunk), error);
  }
  if (chunk.partial) {
    *stop = true;
    scan->index->loss = cutShort(
        scan->file, chunk.pos,
        "chunk record cut short: " + std::to_string(chunk.data_len) + " of its " +
            std::to_string(frame.data_len) + " data bytes present, read up to its first record "
                                             "cut short");
  }
  return learnChunk(scan, std::move(chunk), error);
}

bool scanConnection(Scan* scan, const RecordFrame& frame, const RecordHeader& header,
                    std::string* error) {
  std::string what;
  Connection c;
  if (!scan->file.readData(frame, frame.data_len, &scan->bytes) ||
      !parseConnection(header, scan->bytes.data(), scan->bytes.size(), &c, &what)) {
    *error = errorAt(scan->file.path(), frame.offset, "connection record: " + what);
    return false;
  }
  c.offset = frame.offset;
  return addConnection(scan->file.path(), std::move(c), scan->index, error);
}

}  // namespace

bool scanChunks(BagFile& file, uint64_t chunks_start, uint64_t limit, BagIndex* index,
                std::string* error) {
  Scan scan{file, std::min(limit, file.size()), index, {}, {}, {}, {}};
  index->scanned = true;
  uint64_t pos = chunks_start;
  for (bool stop = false; !stop;) {
    RecordFrame frame;
    RecordHeader header;
    std::string what;
    const ReadStatus status = file.readRecord(pos, scan.limit, &frame, &header, &what);
    index->scan_end = pos;
    if (status == ReadStatus::kEnd) break;
    if (status == ReadStatus::kHeaderCut) {
      index->loss = cutShort(file, pos, "record cut short");
      break;
    }
    uint8_t op = 0;
    if (status == ReadStatus::kBadHeader || !header.op(&op, &what)) {
      *error = errorAt(file.path(), pos, "record: " + what);
      return false;
    }
    if (op == uint8_t(Op::kChunk)) {
      if (!scanChunk(&scan, frame, &stop, error)) return false;
    } else if (status == ReadStatus::kDataCut && op == uint8_t(Op::kIndexData)) {
      // The index of the chunk before it: no message is in it.
      index->scan_end = frame.end();
      index->notice = errorAt(file.path(), pos, "index data record cut short (no messages lost)");
      break;
    } else if (status == ReadStatus::kDataCut) {
      index->loss = cutShort(file, pos, std::string(opName(op)) + " cut short");
      break;
    } else if (op == uint8_t(Op::kConnection)) {
      if (!scanConnection(&scan, frame, header, error)) return false;
    }
    pos = frame.end();
  }
  return true;
}

}  // namespace deepnav::rosbag
