#include "drivers/mcap/crc32.h"
#include "drivers/mcap/diagnostic_text.h"
#include "drivers/mcap/format.h"
#include "drivers/mcap/reader.h"

// One Chunk record's records: decompressed (zstd, LZ4) into the reused buffer, checked against the
// chunk's size and CRC, then walked record by record. A chunk that fails is skipped, counted in
// skippedChunks() and warned about; the rest of the file is still read.
namespace deepnav::mcap {
namespace {

// A corrupt uncompressed_size must not make the reader allocate without bound.
constexpr uint64_t kMaxChunkUncompressedBytes = uint64_t(1) << 30;

}  // namespace

bool Reader::unpackChunk(const uint8_t* content, size_t size, uint64_t offset,
                         const uint8_t** records, size_t* records_size) {
  *records = nullptr;
  *records_size = 0;
  ChunkView v;
  if (!parseChunk(ByteCursor(content, size), &v)) return fail("malformed Chunk record", offset);
  const auto skip = [&](const std::string& why) {
    ++skipped_chunks_;
    warn("chunk skipped: " + why, offset);
    *records = nullptr;
    *records_size = 0;
    return true;
  };
  if (v.uncompressed_size > kMaxChunkUncompressedBytes) {
    return skip("claims " + std::to_string(v.uncompressed_size) + " uncompressed bytes");
  }
  if (v.compression.empty()) {
    *records = v.records;
    *records_size = size_t(v.records_size);
  } else {
    chunk_buffer_.resize(size_t(v.uncompressed_size));
    std::string why;
    if (!decompressor_.decompress(v.compression, v.records, size_t(v.records_size),
                                  chunk_buffer_.data(), chunk_buffer_.size(), &why)) {
      return skip(why);
    }
    *records = chunk_buffer_.data();
    *records_size = chunk_buffer_.size();
  }
  if (*records_size != v.uncompressed_size) {
    return skip("holds " + std::to_string(*records_size) + " bytes, header says " +
                std::to_string(v.uncompressed_size));
  }
  const uint32_t crc = crc32(*records, *records_size);
  if (v.uncompressed_crc != 0 && crc != v.uncompressed_crc) {
    return skip("CRC mismatch (chunk says " + hex32(v.uncompressed_crc) + ", computed " +
                hex32(crc) + ")");
  }
  return true;
}

bool Reader::forEachChunkRecord(const uint8_t* records, size_t size, uint64_t chunk_offset,
                                const ChunkRecordVisitor& visit) {
  size_t pos = 0;
  while (pos < size) {
    const uint8_t op = records[pos];
    const bool fits = size - pos >= kRecordPrefixSize &&
                      le64(records + pos + 1) <= size - pos - kRecordPrefixSize;
    const size_t length = fits ? size_t(le64(records + pos + 1)) : 0;
    if (!fits || !visit(op, records + pos + kRecordPrefixSize, length, pos)) {
      ++skipped_chunks_;
      warn("malformed " + opcodeName(op) + " record " + std::to_string(pos) +
               " bytes into the chunk; rest of the chunk skipped",
           chunk_offset);
      return false;
    }
    pos += kRecordPrefixSize + length;
  }
  return true;
}

}  // namespace deepnav::mcap
