#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

#include "drivers/mcap/compression.h"

namespace deepnav::mcap {

// Everything the Writer sizes its buffers from at open(). Defaults suit the nav recorder:
// about one chunk per second, so a kill -9 or a power cut loses at most ~1 s of data.
struct WriterOptions {
  Compression compression = Compression::kZstd;
  // zstd: 1 (fast) .. 19; lz4: 0 (fast) .. 12 (HC). The recorder runs on a 2-core board.
  int compression_level = 1;
  // A chunk closes once its uncompressed records reach this size [bytes].
  size_t chunk_size_bytes = 1024 * 1024;
  // ... or before a message that would stretch its log-time span beyond this [ns].
  uint64_t chunk_max_duration_ns = 1'000'000'000;
  // Largest message expected [bytes]; the chunk buffer holds chunk_size_bytes plus one such
  // message without growing. A bigger message is still written, at the cost of one allocation.
  size_t max_message_bytes = 256 * 1024;
  // Message-index entries reserved per channel at addChannel() (messages of one channel in one
  // chunk); past this the index vector grows once and keeps its capacity.
  size_t index_entries_per_channel = 1024;
  // Chunks reserved in the summary's chunk index (one per second: ~4.5 h).
  size_t expected_chunks = 16 * 1024;
  // CRC32 of each chunk's records, of the data section and of the summary.
  bool enable_crcs = true;
  // fdatasync after each chunk: survives a power cut, not only a crash of the process.
  bool sync_each_chunk = false;
  std::string profile = "ros2";
  std::string library = "deepnav";
};

}  // namespace deepnav::mcap
