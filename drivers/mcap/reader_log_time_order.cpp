#include <algorithm>
#include <queue>

#include "drivers/mcap/format.h"
#include "drivers/mcap/reader.h"

// readAllInLogTimeOrder(): a k-way merge over the chunks sorted by start time, decompressing a
// chunk only when the merge reaches its start, so memory holds only chunks whose time ranges
// overlap.
namespace deepnav::mcap {

bool Reader::loadChunkAt(const ChunkInfo& chunk, std::vector<uint8_t>* records) {
  records->clear();
  if (!chunkInfoInBounds(chunk) ||
      !readContent(chunk.chunk_start_offset, chunk.chunk_length, &record_buffer_) ||
      record_buffer_[0] != uint8_t(Opcode::kChunk) ||
      le64(record_buffer_.data() + 1) != chunk.chunk_length - kRecordPrefixSize) {
    return fail("chunk index points to no Chunk record", chunk.chunk_start_offset);
  }
  const uint8_t* data = nullptr;
  size_t size = 0;
  if (!unpackChunk(record_buffer_.data() + kRecordPrefixSize,
                   record_buffer_.size() - kRecordPrefixSize, chunk.chunk_start_offset, &data,
                   &size)) {
    return false;
  }
  records->assign(data, data + size);
  return true;
}

// Messages of the decompressed chunks not yet delivered, earliest log time on top. Each chunk's
// records live in a slot until its last message is out.
struct Reader::LogTimeMerge {
  struct Pending {
    uint64_t log_time_ns;
    uint64_t chunk_offset;  // ties in log time go in file order
    size_t content_at;      // Message content inside the slot's records
    size_t content_size;
    size_t slot;
  };
  struct Later {
    bool operator()(const Pending& a, const Pending& b) const {
      if (a.log_time_ns != b.log_time_ns) return a.log_time_ns > b.log_time_ns;
      if (a.chunk_offset != b.chunk_offset) return a.chunk_offset > b.chunk_offset;
      return a.content_at > b.content_at;
    }
  };

  size_t takeSlot() {
    if (!free_slots.empty()) {
      const size_t slot = free_slots.back();
      free_slots.pop_back();
      return slot;
    }
    slots.emplace_back();
    remaining.push_back(0);
    return slots.size() - 1;
  }

  std::priority_queue<Pending, std::vector<Pending>, Later> heap;
  std::vector<std::vector<uint8_t>> slots;
  std::vector<size_t> remaining;
  std::vector<size_t> free_slots;
};

bool Reader::mergeChunk(const ChunkInfo& chunk, LogTimeMerge* merge) {
  const size_t slot = merge->takeSlot();
  if (!loadChunkAt(chunk, &merge->slots[slot])) return false;
  const std::vector<uint8_t>& records = merge->slots[slot];
  forEachChunkRecord(records.data(), records.size(), chunk.chunk_start_offset,
                     [&](uint8_t op, const uint8_t* content, size_t size, uint64_t at) {
                       if (op == uint8_t(Opcode::kSchema) || op == uint8_t(Opcode::kChannel)) {
                         return definitionRecord(op, content, size, chunk.chunk_start_offset);
                       }
                       if (op != uint8_t(Opcode::kMessage)) return true;
                       MessageView m;
                       if (!parseMessage(ByteCursor(content, size), &m)) return false;
                       merge->heap.push({m.log_time_ns, chunk.chunk_start_offset,
                                         size_t(at) + kRecordPrefixSize, size, slot});
                       ++merge->remaining[slot];
                       return true;
                     });
  if (merge->remaining[slot] == 0) merge->free_slots.push_back(slot);
  return true;
}

bool Reader::readAllInLogTimeOrder(const MessageCallback& callback) {
  if (data_start_ == 0) {
    error_ = "mcap reader: no file open";
    return false;
  }
  if (has_unchunked_messages_) return readAllSortedInMemory(callback);
  error_.clear();
  std::vector<ChunkInfo> order = chunks_;
  std::sort(order.begin(), order.end(), [](const ChunkInfo& a, const ChunkInfo& b) {
    if (a.message_start_time_ns != b.message_start_time_ns) {
      return a.message_start_time_ns < b.message_start_time_ns;
    }
    return a.chunk_start_offset < b.chunk_start_offset;
  });
  LogTimeMerge merge;
  size_t next = 0;
  while (!merge.heap.empty() || next < order.size()) {
    // A chunk starting no later than the earliest pending message may hold an earlier one.
    if (next < order.size() &&
        (merge.heap.empty() || order[next].message_start_time_ns <= merge.heap.top().log_time_ns)) {
      if (!mergeChunk(order[next++], &merge)) return false;
      continue;
    }
    const LogTimeMerge::Pending p = merge.heap.top();
    merge.heap.pop();
    MessageView m;
    parseMessage(ByteCursor(merge.slots[p.slot].data() + p.content_at, p.content_size), &m);
    callback(m);
    if (--merge.remaining[p.slot] == 0) merge.free_slots.push_back(p.slot);
  }
  return true;
}

// Files with messages outside chunks (not ours) have no chunk order to merge; sort them all.
bool Reader::readAllSortedInMemory(const MessageCallback& callback) {
  struct Copy {
    MessageView view;
    size_t data_at;
  };
  std::vector<Copy> copies;
  std::vector<uint8_t> bytes;
  const bool ok = readAll([&](const MessageView& m) {
    copies.push_back(Copy{m, bytes.size()});
    bytes.insert(bytes.end(), m.data, m.data + m.size);
  });
  std::stable_sort(copies.begin(), copies.end(), [](const Copy& a, const Copy& b) {
    return a.view.log_time_ns < b.view.log_time_ns;
  });
  for (Copy& c : copies) {
    c.view.data = bytes.data() + c.data_at;
    callback(c.view);
  }
  return ok;
}

}  // namespace deepnav::mcap
