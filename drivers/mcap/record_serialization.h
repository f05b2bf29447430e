#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

#include "drivers/mcap/format.h"
#include "drivers/mcap/records.h"

// Serialises whole MCAP records (opcode, length, content) onto the end of a byte vector, field
// by field in the order of the spec's tables.
namespace deepnav::mcap {

struct MessageIndexEntry {
  uint64_t log_time_ns;
  uint64_t offset;  // from the start of the chunk's uncompressed records
};

// Channel id -> file offset of that channel's Message Index record after a chunk.
using MessageIndexOffset = std::pair<uint16_t, uint64_t>;

void appendHeader(std::vector<uint8_t>& out, const Header& header);
void appendSchema(std::vector<uint8_t>& out, const Schema& schema);
void appendChannel(std::vector<uint8_t>& out, const Channel& channel);
void appendMessage(std::vector<uint8_t>& out, const MessageView& message);
void appendMessageIndex(std::vector<uint8_t>& out, uint16_t channel_id,
                        const MessageIndexEntry* entries, size_t count);
// Everything of a Chunk record before its compressed records bytes, which follow it directly.
void appendChunkPrefix(std::vector<uint8_t>& out, const ChunkInfo& chunk,
                       uint32_t uncompressed_crc);
void appendChunkIndex(std::vector<uint8_t>& out, const ChunkInfo& chunk,
                      const MessageIndexOffset* offsets, size_t offset_count);
void appendStatistics(std::vector<uint8_t>& out, const Statistics& stats);
void appendMetadata(std::vector<uint8_t>& out, const Metadata& metadata);
void appendMetadataIndex(std::vector<uint8_t>& out, uint64_t offset, uint64_t length,
                         std::string_view name);
void appendDataEnd(std::vector<uint8_t>& out, uint32_t data_section_crc);
void appendSummaryOffset(std::vector<uint8_t>& out, Opcode group, uint64_t start, uint64_t length);

}  // namespace deepnav::mcap
