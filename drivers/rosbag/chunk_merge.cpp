#include "drivers/rosbag/chunk_merge.h"

#include <algorithm>

#include "drivers/rosbag/chunk_loading.h"

namespace deepnav::rosbag {
namespace {

bool before(const MessageEntry& a, uint64_t a_pos, const MessageEntry& b, uint64_t b_pos) {
  if (a.time_ns != b.time_ns) return a.time_ns < b.time_ns;
  if (a_pos != b_pos) return a_pos < b_pos;
  return a.order < b.order;
}

}  // namespace

ChunkMerge::ChunkMerge(const BagFile& file, const BagIndex& index) : file_(file), index_(index) {
  for (const ChunkRef& c : index_.chunks) order_.push_back(&c);
  std::sort(order_.begin(), order_.end(), [](const ChunkRef* a, const ChunkRef* b) {
    return a->start_ns != b->start_ns ? a->start_ns < b->start_ns : a->pos < b->pos;
  });
}

bool ChunkMerge::checkEntries(const ChunkRef& chunk, std::string* error) const {
  for (const MessageEntry& m : content_.messages) {
    if (index_.connections.count(m.conn) == 0) {
      *error = errorAt(file_.path(), chunk.pos,
                       "chunk record: a message data record (byte " +
                           std::to_string(m.data_offset) +
                           " of the decompressed chunk) names connection " +
                           std::to_string(m.conn) + ", which no connection record defines");
      return false;
    }
    if (m.time_ns < chunk.start_ns || m.time_ns > chunk.end_ns) {
      *error = errorAt(file_.path(), chunk.pos,
                       "chunk record: holds a message at " + std::to_string(m.time_ns) +
                           " ns, its chunk info says it spans " + std::to_string(chunk.start_ns) +
                           " to " + std::to_string(chunk.end_ns) + " ns: the index is inconsistent");
      return false;
    }
  }
  return true;
}

bool ChunkMerge::load(const ChunkRef& chunk, std::string* error) {
  auto open = std::make_unique<OpenChunk>();
  open->chunk = &chunk;
  if (!loadChunk(file_, chunk, &decompressor_, &compressed_, &open->bytes, &content_, error) ||
      !checkEntries(chunk, error)) {
    return false;
  }
  open->entries = content_.messages;
  std::sort(open->entries.begin(), open->entries.end(),
            [](const MessageEntry& a, const MessageEntry& b) { return before(a, 0, b, 0); });
  if (!open->entries.empty()) open_.push_back(std::move(open));
  return true;
}

size_t ChunkMerge::earliest() const {
  size_t best = open_.size();
  for (size_t i = 0; i < open_.size(); ++i) {
    const OpenChunk& c = *open_[i];
    if (best == open_.size() ||
        before(c.entries[c.next], c.chunk->pos, open_[best]->entries[open_[best]->next],
               open_[best]->chunk->pos)) {
      best = i;
    }
  }
  return best;
}

bool ChunkMerge::deliver(size_t which, const foreign::ForeignContainer::Callback& callback) {
  OpenChunk& c = *open_[which];
  const MessageEntry& m = c.entries[c.next];
  const Connection& conn = index_.connections.at(m.conn);
  foreign::ForeignMessage msg;
  msg.topic = conn.topic;
  msg.type = conn.type;
  msg.serialization = foreign::Serialization::kRos1;
  msg.log_time_ns = m.time_ns;
  msg.data = c.bytes.data() + m.data_offset;
  msg.size = m.data_size;
  const bool go_on = callback(msg);
  if (++c.next == c.entries.size()) open_.erase(open_.begin() + std::ptrdiff_t(which));
  return go_on;
}

bool ChunkMerge::run(const foreign::ForeignContainer::Callback& callback, std::string* error) {
  size_t next_chunk = 0;
  for (;;) {
    size_t e = earliest();
    while (next_chunk < order_.size() &&
           (e == open_.size() ||
            order_[next_chunk]->start_ns <= open_[e]->entries[open_[e]->next].time_ns)) {
      if (!load(*order_[next_chunk++], error)) return false;
      e = earliest();
    }
    if (e == open_.size()) return true;
    if (!deliver(e, callback)) {
      stopped_ = true;
      return true;
    }
  }
}

}  // namespace deepnav::rosbag
