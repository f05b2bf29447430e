#include "drivers/mcap/record_parsing.h"

#include <cstdio>

namespace deepnav::mcap {

bool parseHeader(ByteCursor c, Header* out) {
  return c.string(&out->profile) && c.string(&out->library);
}

bool parseFooter(ByteCursor c, Footer* out) {
  return c.u64(&out->summary_start) && c.u64(&out->summary_offset_start) &&
         c.u32(&out->summary_crc);
}

bool parseSchema(ByteCursor c, Schema* out) {
  std::string_view data;
  if (!c.u16(&out->id) || !c.string(&out->name) || !c.string(&out->encoding) ||
      !c.stringView(&data)) {
    return false;
  }
  out->data.assign(data.begin(), data.end());
  return true;
}

bool parseChannel(ByteCursor c, Channel* out) {
  return c.u16(&out->id) && c.u16(&out->schema_id) && c.string(&out->topic) &&
         c.string(&out->message_encoding) && c.stringMap(&out->metadata);
}

bool parseMessage(ByteCursor c, MessageView* out) {
  if (!c.u16(&out->channel_id) || !c.u32(&out->sequence) || !c.u64(&out->log_time_ns) ||
      !c.u64(&out->publish_time_ns)) {
    return false;
  }
  out->data = c.here();
  out->size = c.remaining();
  return true;
}

namespace {

bool readChunkPrefix(ByteCursor& c, ChunkView* out) {
  return c.u64(&out->message_start_time_ns) && c.u64(&out->message_end_time_ns) &&
         c.u64(&out->uncompressed_size) && c.u32(&out->uncompressed_crc) &&
         c.stringView(&out->compression) && c.u64(&out->records_size);
}

}  // namespace

bool parseChunkPrefix(ByteCursor c, ChunkView* out) { return readChunkPrefix(c, out); }

bool parseChunk(ByteCursor c, ChunkView* out) {
  return readChunkPrefix(c, out) && c.bytes(out->records_size, &out->records);
}

bool parseMessageIndexCount(ByteCursor c, uint16_t* channel_id, uint64_t* entry_count) {
  uint32_t bytes = 0;
  if (!c.u16(channel_id) || !c.u32(&bytes) || bytes % 16 != 0 || bytes > c.remaining()) {
    return false;
  }
  *entry_count = bytes / 16;
  return true;
}

bool parseChunkIndex(ByteCursor c, ChunkInfo* out) {
  ByteCursor offsets(nullptr, 0);
  return c.u64(&out->message_start_time_ns) && c.u64(&out->message_end_time_ns) &&
         c.u64(&out->chunk_start_offset) && c.u64(&out->chunk_length) && c.block(&offsets) &&
         c.u64(&out->message_index_length) && c.string(&out->compression) &&
         c.u64(&out->compressed_size) && c.u64(&out->uncompressed_size);
}

bool parseStatistics(ByteCursor c, Statistics* out) {
  ByteCursor counts(nullptr, 0);
  if (!c.u64(&out->message_count) || !c.u16(&out->schema_count) || !c.u32(&out->channel_count) ||
      !c.u32(&out->attachment_count) || !c.u32(&out->metadata_count) || !c.u32(&out->chunk_count) ||
      !c.u64(&out->message_start_time_ns) || !c.u64(&out->message_end_time_ns) ||
      !c.block(&counts)) {
    return false;
  }
  out->channel_message_counts.clear();
  while (counts.remaining() > 0) {
    uint16_t channel_id = 0;
    uint64_t count = 0;
    if (!counts.u16(&channel_id) || !counts.u64(&count)) return false;
    out->channel_message_counts[channel_id] = count;
  }
  return true;
}

bool parseMetadata(ByteCursor c, Metadata* out) {
  return c.string(&out->name) && c.stringMap(&out->metadata);
}

bool parseMetadataIndex(ByteCursor c, MetadataIndex* out) {
  return c.u64(&out->offset) && c.u64(&out->length) && c.string(&out->name);
}

bool parseDataEnd(ByteCursor c, uint32_t* data_section_crc) { return c.u32(data_section_crc); }

std::string opcodeName(uint8_t opcode) {
  static constexpr const char* kNames[] = {"invalid opcode 0x00",
                                           "Header",
                                           "Footer",
                                           "Schema",
                                           "Channel",
                                           "Message",
                                           "Chunk",
                                           "MessageIndex",
                                           "ChunkIndex",
                                           "Attachment",
                                           "AttachmentIndex",
                                           "Statistics",
                                           "Metadata",
                                           "MetadataIndex",
                                           "SummaryOffset",
                                           "DataEnd"};
  if (opcode < sizeof(kNames) / sizeof(kNames[0])) return kNames[opcode];
  char buf[16];
  std::snprintf(buf, sizeof(buf), "opcode 0x%02X", opcode);
  return buf;
}

}  // namespace deepnav::mcap
