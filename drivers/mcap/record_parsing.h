#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "drivers/mcap/byte_cursor.h"
#include "drivers/mcap/records.h"

// Parses the content of single MCAP records (what follows opcode and length). Each parser reads
// the fields it knows and ignores any trailing bytes, as the spec asks of readers so that records
// can grow new fields. False means the content is too short or a length inside it is wrong.
namespace deepnav::mcap {

struct Footer {
  uint64_t summary_start = 0;
  uint64_t summary_offset_start = 0;
  uint32_t summary_crc = 0;
};

// A Chunk record's fields; `records` points into the parsed content.
struct ChunkView {
  uint64_t message_start_time_ns = 0;
  uint64_t message_end_time_ns = 0;
  uint64_t uncompressed_size = 0;
  uint32_t uncompressed_crc = 0;
  std::string_view compression;
  const uint8_t* records = nullptr;
  uint64_t records_size = 0;
};

struct MetadataIndex {
  uint64_t offset = 0;
  uint64_t length = 0;
  std::string name;
};

bool parseHeader(ByteCursor c, Header* out);
bool parseFooter(ByteCursor c, Footer* out);
bool parseSchema(ByteCursor c, Schema* out);
bool parseChannel(ByteCursor c, Channel* out);
bool parseMessage(ByteCursor c, MessageView* out);
bool parseChunk(ByteCursor c, ChunkView* out);
// Only the fixed fields and the compression name: enough to index a chunk without its payload.
bool parseChunkPrefix(ByteCursor c, ChunkView* out);
// Channel id and number of entries of a Message Index record.
bool parseMessageIndexCount(ByteCursor c, uint16_t* channel_id, uint64_t* entry_count);
bool parseChunkIndex(ByteCursor c, ChunkInfo* out);
bool parseStatistics(ByteCursor c, Statistics* out);
bool parseMetadata(ByteCursor c, Metadata* out);
bool parseMetadataIndex(ByteCursor c, MetadataIndex* out);
bool parseDataEnd(ByteCursor c, uint32_t* data_section_crc);

// "Chunk", "Schema", ... for messages; "opcode 0x42" for unknown ones.
std::string opcodeName(uint8_t opcode);

}  // namespace deepnav::mcap
