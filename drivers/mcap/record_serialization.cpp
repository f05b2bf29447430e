#include "drivers/mcap/record_serialization.h"

#include "drivers/mcap/record_builder.h"

namespace deepnav::mcap {
namespace {

void appendStringMap(std::vector<uint8_t>& out, const std::map<std::string, std::string>& m) {
  const size_t at = beginU32Block(out);
  for (const auto& [key, value] : m) {
    putString(out, key);
    putString(out, value);
  }
  endU32Block(out, at);
}

}  // namespace

void appendHeader(std::vector<uint8_t>& out, const Header& header) {
  const size_t at = beginRecord(out, Opcode::kHeader);
  putString(out, header.profile);
  putString(out, header.library);
  endRecord(out, at);
}

void appendSchema(std::vector<uint8_t>& out, const Schema& schema) {
  const size_t at = beginRecord(out, Opcode::kSchema);
  putU16(out, schema.id);
  putString(out, schema.name);
  putString(out, schema.encoding);
  putU32(out, uint32_t(schema.data.size()));
  putBytes(out, schema.data.data(), schema.data.size());
  endRecord(out, at);
}

void appendChannel(std::vector<uint8_t>& out, const Channel& channel) {
  const size_t at = beginRecord(out, Opcode::kChannel);
  putU16(out, channel.id);
  putU16(out, channel.schema_id);
  putString(out, channel.topic);
  putString(out, channel.message_encoding);
  appendStringMap(out, channel.metadata);
  endRecord(out, at);
}

void appendMessage(std::vector<uint8_t>& out, const MessageView& m) {
  putU8(out, uint8_t(Opcode::kMessage));
  putU64(out, kMessageFixedSize + m.size);
  putU16(out, m.channel_id);
  putU32(out, m.sequence);
  putU64(out, m.log_time_ns);
  putU64(out, m.publish_time_ns);
  putBytes(out, m.data, m.size);
}

void appendMessageIndex(std::vector<uint8_t>& out, uint16_t channel_id,
                        const MessageIndexEntry* entries, size_t count) {
  const size_t at = beginRecord(out, Opcode::kMessageIndex);
  putU16(out, channel_id);
  putU32(out, uint32_t(count * 16));
  for (size_t i = 0; i < count; ++i) {
    putU64(out, entries[i].log_time_ns);
    putU64(out, entries[i].offset);
  }
  endRecord(out, at);
}

void appendChunkPrefix(std::vector<uint8_t>& out, const ChunkInfo& chunk,
                       uint32_t uncompressed_crc) {
  const std::string_view compression = chunk.compression;
  putU8(out, uint8_t(Opcode::kChunk));
  putU64(out, kChunkFixedSize + 4 + compression.size() + 8 + chunk.compressed_size);
  putU64(out, chunk.message_start_time_ns);
  putU64(out, chunk.message_end_time_ns);
  putU64(out, chunk.uncompressed_size);
  putU32(out, uncompressed_crc);
  putString(out, compression);
  putU64(out, chunk.compressed_size);
}

void appendChunkIndex(std::vector<uint8_t>& out, const ChunkInfo& chunk,
                      const MessageIndexOffset* offsets, size_t offset_count) {
  const size_t at = beginRecord(out, Opcode::kChunkIndex);
  putU64(out, chunk.message_start_time_ns);
  putU64(out, chunk.message_end_time_ns);
  putU64(out, chunk.chunk_start_offset);
  putU64(out, chunk.chunk_length);
  const size_t map_at = beginU32Block(out);
  for (size_t i = 0; i < offset_count; ++i) {
    putU16(out, offsets[i].first);
    putU64(out, offsets[i].second);
  }
  endU32Block(out, map_at);
  putU64(out, chunk.message_index_length);
  putString(out, chunk.compression);
  putU64(out, chunk.compressed_size);
  putU64(out, chunk.uncompressed_size);
  endRecord(out, at);
}

void appendStatistics(std::vector<uint8_t>& out, const Statistics& s) {
  const size_t at = beginRecord(out, Opcode::kStatistics);
  putU64(out, s.message_count);
  putU16(out, s.schema_count);
  putU32(out, s.channel_count);
  putU32(out, s.attachment_count);
  putU32(out, s.metadata_count);
  putU32(out, s.chunk_count);
  putU64(out, s.message_start_time_ns);
  putU64(out, s.message_end_time_ns);
  const size_t map_at = beginU32Block(out);
  for (const auto& [channel_id, count] : s.channel_message_counts) {
    putU16(out, channel_id);
    putU64(out, count);
  }
  endU32Block(out, map_at);
  endRecord(out, at);
}

void appendMetadata(std::vector<uint8_t>& out, const Metadata& metadata) {
  const size_t at = beginRecord(out, Opcode::kMetadata);
  putString(out, metadata.name);
  appendStringMap(out, metadata.metadata);
  endRecord(out, at);
}

void appendMetadataIndex(std::vector<uint8_t>& out, uint64_t offset, uint64_t length,
                         std::string_view name) {
  const size_t at = beginRecord(out, Opcode::kMetadataIndex);
  putU64(out, offset);
  putU64(out, length);
  putString(out, name);
  endRecord(out, at);
}

void appendDataEnd(std::vector<uint8_t>& out, uint32_t data_section_crc) {
  const size_t at = beginRecord(out, Opcode::kDataEnd);
  putU32(out, data_section_crc);
  endRecord(out, at);
}

void appendSummaryOffset(std::vector<uint8_t>& out, Opcode group, uint64_t start, uint64_t length) {
  const size_t at = beginRecord(out, Opcode::kSummaryOffset);
  putU8(out, uint8_t(group));
  putU64(out, start);
  putU64(out, length);
  endRecord(out, at);
}

}  // namespace deepnav::mcap
