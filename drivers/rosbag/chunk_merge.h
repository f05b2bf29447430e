#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "drivers/foreign/foreign_message.h"
#include "drivers/rosbag/bag_file.h"
#include "drivers/rosbag/bag_index.h"
#include "drivers/rosbag/chunk_decompression.h"
#include "drivers/rosbag/chunk_records.h"

// The messages of all chunks in log-time order, ties in file order. Chunks are taken by start
// time and a chunk is decompressed only when its start time is reached, so memory holds the
// chunks whose time ranges overlap (one or two in a recording), never the whole bag.
namespace deepnav::rosbag {

class ChunkMerge {
 public:
  ChunkMerge(const BagFile& file, const BagIndex& index);
  // Calls `callback` for every message; false with *error on a damaged chunk.
  bool run(const foreign::ForeignContainer::Callback& callback, std::string* error);
  bool stopped() const { return stopped_; }  // the callback asked to stop

 private:
  struct OpenChunk {
    const ChunkRef* chunk = nullptr;
    std::vector<uint8_t> bytes;
    std::vector<MessageEntry> entries;  // by (time, file order)
    size_t next = 0;
  };

  bool load(const ChunkRef& chunk, std::string* error);
  bool checkEntries(const ChunkRef& chunk, std::string* error) const;
  size_t earliest() const;  // index into open_, open_.size() when none
  bool deliver(size_t which, const foreign::ForeignContainer::Callback& callback);

  const BagFile& file_;
  const BagIndex& index_;
  std::vector<const ChunkRef*> order_;  // by (start time, file position)
  std::vector<std::unique_ptr<OpenChunk>> open_;
  ChunkDecompressor decompressor_;
  std::vector<uint8_t> compressed_;
  ChunkContent content_;
  bool stopped_ = false;
};

}  // namespace deepnav::rosbag
