#pragma once
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/mcap/compression.h"
#include "drivers/mcap/record_serialization.h"
#include "drivers/mcap/records.h"
#include "drivers/mcap/writer_options.h"

namespace deepnav::mcap {

// Writes an indexed, chunked MCAP file:
//   magic, Header, { [Schema] [Channel] Chunk MessageIndex... | Metadata }..., DataEnd,
//   summary (Schema, Channel, Statistics, ChunkIndex, MetadataIndex), SummaryOffsets, Footer,
//   magic.
// A Schema/Channel record goes to the data section (outside any chunk) just before the first
// chunk holding one of its messages, so a reader that skips a damaged chunk still knows every
// channel; the summary repeats them all.
// Each closed chunk is written and fflush()ed at once: a crash loses at most the open chunk, and
// Reader recovers every complete chunk of a file that has no summary.
// Buffers are reserved at open(); write() does not allocate once every channel has seen its
// busiest chunk. Not thread-safe: one recorder thread owns a Writer. Errors are returned (and
// kept in lastError()), never thrown.
class Writer {
 public:
  Writer() = default;
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  bool open(const std::string& path, const WriterOptions& options, std::string* error);
  // Returns the new schema id (1, 2, ...) or 0 on error.
  uint16_t addSchema(std::string_view name, std::string_view encoding, std::string_view data);
  // schema_id 0 means "no schema". With the "ros2" profile, metadata gains
  // offered_qos_profiles = "" unless given. Returns the new channel id (1, 2, ...) or 0 on error.
  uint16_t addChannel(uint16_t schema_id, std::string_view topic, std::string_view message_encoding,
                      const std::map<std::string, std::string>& metadata = {});
  bool write(uint16_t channel_id, uint32_t sequence, uint64_t log_time_ns, uint64_t publish_time_ns,
             const uint8_t* data, size_t size);
  // A Metadata record in the data section, indexed in the summary.
  bool writeMetadata(std::string_view name, const std::map<std::string, std::string>& metadata);
  // Closes the open chunk now (if it holds a message) and pushes it to the OS.
  bool flush();
  // Closes the last chunk, writes DataEnd, the summary and the footer. True if every byte of the
  // file was written. The Writer can be opened again afterwards.
  bool close(std::string* error);

  bool isOpen() const { return file_ != nullptr; }
  const std::string& lastError() const { return error_; }
  uint64_t messageCount() const { return message_count_; }
  size_t chunkCount() const { return chunks_.size(); }

 private:
  struct SchemaState {
    Schema schema;
    bool in_file = false;
  };
  struct ChannelState {
    Channel channel;
    bool in_file = false;
    uint64_t message_count = 0;
    std::vector<MessageIndexEntry> index;  // this chunk's messages on the channel
  };
  struct ChunkRecord {
    ChunkInfo info;
    size_t offsets_begin = 0;  // into message_index_offsets_
    size_t offsets_count = 0;
  };
  struct MetadataIndexEntry {
    uint64_t offset;
    uint64_t length;
    std::string name;
  };

  bool fail(std::string message);
  bool writeOut(const uint8_t* data, size_t size);
  bool writeOut(const std::vector<uint8_t>& bytes) { return writeOut(bytes.data(), bytes.size()); }
  bool chunkWouldSpanTooLong(uint64_t log_time_ns) const;
  void noteMessage(ChannelState& channel, uint64_t log_time_ns);
  bool closeChunk();
  bool compressChunk(const uint8_t** payload, size_t* payload_size);
  bool writeDefinitions(bool only_channels_in_chunk);
  bool writeMessageIndexes(ChunkInfo* info);
  void resetChunk();
  bool pushToOs();
  bool writeDataEnd();
  Statistics statistics() const;
  size_t appendSummary(std::vector<uint8_t>& out) const;
  bool writeSummaryAndFooter();
  void resetState();

  WriterOptions options_;
  std::string path_;
  std::FILE* file_ = nullptr;
  std::string error_;
  bool failed_ = false;
  uint64_t file_offset_ = 0;
  bool in_data_section_ = false;
  uint32_t data_crc_ = 0;

  ChunkCompressor compressor_;
  std::vector<uint8_t> chunk_buffer_;       // uncompressed records of the open chunk
  std::vector<uint8_t> compressed_buffer_;  // its compressed form
  std::vector<uint8_t> scratch_;            // record prefixes, definitions, message indexes
  uint64_t chunk_start_ns_ = 0;
  uint64_t chunk_end_ns_ = 0;
  size_t chunk_message_count_ = 0;

  std::vector<SchemaState> schemas_;    // id - 1
  std::vector<ChannelState> channels_;  // id - 1
  std::vector<ChunkRecord> chunks_;
  std::vector<MessageIndexOffset> message_index_offsets_;
  std::vector<MetadataIndexEntry> metadata_index_;
  uint64_t message_count_ = 0;
  uint64_t message_start_ns_ = 0;
  uint64_t message_end_ns_ = 0;
};

}  // namespace deepnav::mcap
