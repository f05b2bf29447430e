#pragma once
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "drivers/mcap/compression.h"
#include "drivers/mcap/random_access_file.h"
#include "drivers/mcap/record_parsing.h"
#include "drivers/mcap/records.h"

namespace deepnav::mcap {

// Reads an MCAP file, ours or any other writer's.
//
// open() reads the header, then the footer and summary (schemas, channels, statistics, chunk
// indexes). A file without a valid footer -- a recording cut off by a crash or power loss -- is
// scanned record by record from the start instead: every complete record before the cut is
// used, truncated() is set and warnings() says where it stopped.
//
// Every length and offset read from the file is checked against the bytes that hold it: a
// corrupt file gives an error naming the file and the byte offset, never a crash. A chunk whose
// CRC does not match (or that does not decompress) is skipped, counted and warned about.
class Reader {
 public:
  using MessageCallback = std::function<void(const MessageView&)>;

  Reader() = default;
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  bool open(const std::string& path, std::string* error);
  void close();

  // All messages in file order (chunk by chunk, records in chunk order). False on a corrupt
  // record, with error() set; messages before it have been delivered.
  bool readAll(const MessageCallback& callback);
  // All messages ordered by log time (ties in file order). Decompresses chunks as the merge
  // needs them, so memory holds only chunks whose time ranges overlap.
  bool readAllInLogTimeOrder(const MessageCallback& callback);

  const std::string& path() const { return path_; }
  const Header& header() const { return header_; }
  const std::map<uint16_t, Schema>& schemas() const { return schemas_; }
  const std::map<uint16_t, Channel>& channels() const { return channels_; }
  const Schema* schema(uint16_t id) const;
  const Channel* channel(uint16_t id) const;
  // From the summary; for a file without one, rebuilt at open() from the records scanned
  // (message counts then come from the Message Index records after each complete chunk).
  const Statistics& statistics() const { return statistics_; }
  bool hasSummary() const { return has_summary_; }
  const std::vector<ChunkInfo>& chunks() const { return chunks_; }
  const std::vector<Metadata>& metadata() const { return metadata_; }

  bool truncated() const { return truncated_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  uint64_t skippedChunks() const { return skipped_chunks_; }
  const std::string& error() const { return error_; }

 private:
  enum class Visit { kContinue, kStop, kError };
  using RecordVisitor = std::function<Visit(uint64_t offset, uint8_t opcode, uint64_t length)>;
  using ChunkRecordVisitor =
      std::function<bool(uint8_t opcode, const uint8_t* content, size_t size, uint64_t offset)>;

  void reset();
  // Forgets the schemas, channels, statistics, chunk list and metadata (summary or scan).
  void clearIndex();
  bool fail(const std::string& what, uint64_t offset);
  void warn(const std::string& what, uint64_t offset);

  // Opening (reader.cpp).
  bool readMagicAndHeader();
  bool readFooter(Footer* footer);
  bool readContent(uint64_t offset, uint64_t length, std::vector<uint8_t>* out);
  bool definitionRecord(uint8_t opcode, const uint8_t* content, size_t size, uint64_t offset);

  // The summary (reader_summary.cpp).
  bool loadSummary(const Footer& footer);
  bool parseSummary(const uint8_t* data, size_t size, uint64_t base,
                    std::vector<MetadataIndex>* metadata_indexes);
  bool chunkInfoInBounds(const ChunkInfo& chunk) const;
  bool loadIndexedMetadata(const std::vector<MetadataIndex>& indexes);
  void discardSummary();

  // The record-by-record walk of the data section, shared by the open() scan and readAll(), and
  // the scan that indexes a file without a summary (reader_scan.cpp).
  bool walkDataSection(const RecordVisitor& visit);
  bool cutOff(uint64_t offset, const std::string& why);
  bool scanDataSection();
  Visit scanRecord(uint64_t offset, uint8_t opcode, uint64_t length);
  bool scanChunk(uint64_t offset, uint64_t length);
  bool scanMessageIndex(uint64_t offset, uint64_t length);
  bool scanUnchunkedMessage(uint64_t offset, uint64_t length);
  void noteScannedTime(uint64_t t_ns);
  void rebuildStatistics();
  void describeCut();

  // A chunk's records: decompressed, checked, walked (reader_chunk.cpp). unpackChunk() is false on a
  // malformed record (error() set); a skipped chunk has no records (*records_size 0).
  bool unpackChunk(const uint8_t* content, size_t size, uint64_t offset, const uint8_t** records,
                     size_t* records_size);
  bool forEachChunkRecord(const uint8_t* records, size_t size, uint64_t chunk_offset,
                          const ChunkRecordVisitor& visit);

  // readAll() (reader_file_order.cpp).
  Visit readAllRecord(uint64_t offset, uint8_t opcode, uint64_t length,
                      const MessageCallback& callback);
  void checkDataCrc(const uint8_t* content, size_t size, uint64_t offset);
  bool deliverChunk(const uint8_t* content, size_t size, uint64_t offset,
                    const MessageCallback& callback);

  // readAllInLogTimeOrder() (reader_log_time_order.cpp).
  struct LogTimeMerge;
  bool loadChunkAt(const ChunkInfo& chunk, std::vector<uint8_t>* records);
  bool mergeChunk(const ChunkInfo& chunk, LogTimeMerge* merge);
  bool readAllSortedInMemory(const MessageCallback& callback);

  std::string path_;
  RandomAccessFile file_;
  Header header_;
  std::map<uint16_t, Schema> schemas_;
  std::map<uint16_t, Channel> channels_;
  Statistics statistics_;
  std::vector<ChunkInfo> chunks_;
  std::vector<Metadata> metadata_;
  bool has_summary_ = false;
  bool footer_valid_ = false;
  bool truncated_ = false;
  bool has_unchunked_messages_ = false;
  uint64_t data_start_ = 0;  // first record after the header
  uint64_t data_end_ = 0;    // no record of the data section reaches past this
  uint64_t walk_end_ = 0;    // end of the last complete record the last walk reached
  std::string cut_reason_;
  uint32_t header_crc_ = 0;  // CRC32 of magic + header, the start of the data-section CRC
  uint32_t data_crc_ = 0;
  std::map<uint16_t, uint64_t> scanned_channel_counts_;
  bool scanned_any_time_ = false;
  uint64_t scanned_start_ns_ = 0;
  uint64_t scanned_end_ns_ = 0;
  uint64_t skipped_chunks_ = 0;
  std::vector<std::string> warnings_;
  std::string error_;

  ChunkDecompressor decompressor_;
  std::vector<uint8_t> record_buffer_;  // reused for every record read
  std::vector<uint8_t> chunk_buffer_;   // reused for every decompressed chunk
};

}  // namespace deepnav::mcap
