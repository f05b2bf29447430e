#include "drivers/rosbag/chunk_loading.h"

#include <algorithm>

#include "drivers/rosbag/bag_records.h"

namespace deepnav::rosbag {

bool locateChunk(BagFile& file, uint64_t pos, uint64_t limit, ChunkRef* chunk, std::string* error) {
  RecordFrame frame;
  RecordHeader header;
  std::string what;
  const ReadStatus status = file.readRecord(pos, limit, &frame, &header, &what);
  if (status == ReadStatus::kEnd || status == ReadStatus::kHeaderCut) {
    *error = errorAt(file.path(), pos, "chunk record: cut short (the file ends at byte " +
                                           std::to_string(file.size()) + ")");
    return false;
  }
  uint8_t op = 0;
  if (status == ReadStatus::kBadHeader || !header.op(&op, &what)) {
    *error = errorAt(file.path(), pos, "chunk record: " + what);
    return false;
  }
  if (op != uint8_t(Op::kChunk)) {
    *error = errorAt(file.path(), pos,
                     "expected a chunk record (op 5), found op " + std::to_string(op) + " (" +
                         std::string(opName(op)) + ")");
    return false;
  }
  ChunkHeaderFields fields;
  if (!parseChunkHeader(header, &fields, &what)) {
    *error = errorAt(file.path(), pos, "chunk record: " + what);
    return false;
  }
  if (!isKnownCompression(fields.compression)) {
    *error = errorAt(file.path(), pos,
                     "chunk record: header field 'compression' is '" + fields.compression +
                         "', this reader knows none, bz2 and lz4");
    return false;
  }
  if (fields.size > kMaxChunkBytes) {
    *error = errorAt(file.path(), pos,
                     "chunk record: header field 'size' is " + std::to_string(fields.size) +
                         " bytes, more than the " + std::to_string(kMaxChunkBytes) +
                         " this reader accepts");
    return false;
  }
  chunk->pos = pos;
  chunk->compression = fields.compression;
  chunk->size = fields.size;
  chunk->data_offset = frame.data_offset;
  chunk->partial = status == ReadStatus::kDataCut;
  chunk->data_len = chunk->partial ? std::min(limit, file.size()) - frame.data_offset
                                   : frame.data_len;
  return true;
}

bool loadChunk(const BagFile& file, const ChunkRef& chunk, ChunkDecompressor* decompressor,
               std::vector<uint8_t>* compressed, std::vector<uint8_t>* bytes,
               ChunkContent* content, std::string* error) {
  compressed->resize(size_t(chunk.data_len));
  if (chunk.data_len > 0 &&
      !file.readAt(chunk.data_offset, size_t(chunk.data_len), compressed->data())) {
    *error = errorAt(file.path(), chunk.data_offset, "chunk data: read error");
    return false;
  }
  std::string what;
  if (chunk.partial) {
    decompressor->decompressPrefix(chunk.compression, compressed->data(), compressed->size(),
                                   chunk.size, bytes);
  } else if (!decompressor->decompress(chunk.compression, compressed->data(), compressed->size(),
                                       chunk.size, bytes, &what)) {
    *error = errorAt(file.path(), chunk.pos, "chunk record: " + what);
    return false;
  }
  uint64_t at = 0;
  if (!parseChunkRecords(bytes->data(), bytes->size(), !chunk.partial, content, &what, &at)) {
    *error = errorAt(file.path(), chunk.pos,
                     "chunk record, byte " + std::to_string(at) + " of its decompressed data: " + what);
    return false;
  }
  return true;
}

}  // namespace deepnav::rosbag
