#include <algorithm>

#include "drivers/mcap/crc32.h"
#include "drivers/mcap/diagnostic_text.h"
#include "drivers/mcap/format.h"
#include "drivers/mcap/reader.h"

// The summary section of a file with a valid footer: schemas, channels, statistics, chunk indexes
// and metadata indexes, checked against the summary CRC and the data section's bounds. Any doubt
// discards it and the data section is scanned instead (reader_scan.cpp).
namespace deepnav::mcap {

bool Reader::loadSummary(const Footer& footer) {
  const uint64_t footer_at = data_end_;
  const uint64_t start = footer.summary_start;
  const uint64_t offsets_at = footer.summary_offset_start;
  if (start < data_start_ || start > footer_at ||
      (offsets_at != 0 && (offsets_at < start || offsets_at > footer_at))) {
    warn("footer points outside the file (summary_start " + std::to_string(start) +
             ", summary_offset_start " + std::to_string(offsets_at) + ")",
         footer_at);
    return false;
  }
  // The summary CRC covers the summary, the summary offsets and the footer up to its CRC field.
  std::vector<uint8_t> bytes(footer_at + kRecordPrefixSize + 16 - start);
  if (!file_.readAt(start, bytes.size(), bytes.data())) return false;
  const uint32_t crc = crc32(bytes.data(), bytes.size());
  if (footer.summary_crc != 0 && crc != footer.summary_crc) {
    warn("summary CRC mismatch (footer says " + hex32(footer.summary_crc) + ", computed " +
             hex32(crc) + "); reading the data section instead",
         start);
    return false;
  }
  data_end_ = start;
  std::vector<MetadataIndex> metadata_indexes;
  const uint64_t records_end = (offsets_at != 0 ? offsets_at : footer_at) - start;
  if (!parseSummary(bytes.data(), records_end, start, &metadata_indexes)) return false;
  for (const ChunkInfo& c : chunks_) {
    if (!chunkInfoInBounds(c)) {
      warn("chunk index points outside the data section (chunk at byte " +
               std::to_string(c.chunk_start_offset) + ")",
           start);
      return false;
    }
  }
  if (!loadIndexedMetadata(metadata_indexes)) return false;
  has_summary_ = true;
  return true;
}

bool Reader::parseSummary(const uint8_t* data, size_t size, uint64_t base,
                          std::vector<MetadataIndex>* metadata_indexes) {
  bool has_statistics = false;
  size_t pos = 0;
  while (pos < size) {
    if (size - pos < kRecordPrefixSize) {
      warn("summary ends inside a record prefix", base + pos);
      return false;
    }
    const uint8_t op = data[pos];
    const uint64_t length = le64(data + pos + 1);
    if (length > size - pos - kRecordPrefixSize) {
      warn(opcodeName(op) + " record runs past the end of the summary", base + pos);
      return false;
    }
    const ByteCursor c(data + pos + kRecordPrefixSize, size_t(length));
    bool ok = true;
    if (op == uint8_t(Opcode::kSchema) || op == uint8_t(Opcode::kChannel)) {
      ok = definitionRecord(op, data + pos + kRecordPrefixSize, size_t(length), base + pos);
    } else if (op == uint8_t(Opcode::kStatistics)) {
      ok = parseStatistics(c, &statistics_);
      has_statistics = true;
    } else if (op == uint8_t(Opcode::kChunkIndex)) {
      ChunkInfo info;
      ok = parseChunkIndex(c, &info);
      chunks_.push_back(std::move(info));
    } else if (op == uint8_t(Opcode::kMetadataIndex)) {
      MetadataIndex index;
      ok = parseMetadataIndex(c, &index);
      metadata_indexes->push_back(std::move(index));
    }
    if (!ok) {
      warn("malformed " + opcodeName(op) + " record in the summary", base + pos);
      return false;
    }
    pos += kRecordPrefixSize + size_t(length);
  }
  std::sort(chunks_.begin(), chunks_.end(), [](const ChunkInfo& a, const ChunkInfo& b) {
    return a.chunk_start_offset < b.chunk_start_offset;
  });
  if (!has_statistics) rebuildStatistics();
  return true;
}

bool Reader::chunkInfoInBounds(const ChunkInfo& c) const {
  return c.chunk_start_offset >= data_start_ && c.chunk_start_offset <= data_end_ &&
         c.chunk_length >= kRecordPrefixSize && c.chunk_length <= data_end_ - c.chunk_start_offset;
}

bool Reader::loadIndexedMetadata(const std::vector<MetadataIndex>& indexes) {
  for (const MetadataIndex& index : indexes) {
    Metadata m;
    const bool in_bounds = index.offset >= data_start_ && index.offset <= data_end_ &&
                           index.length >= kRecordPrefixSize &&
                           index.length <= data_end_ - index.offset;
    if (!in_bounds || !readContent(index.offset, index.length, &record_buffer_) ||
        record_buffer_[0] != uint8_t(Opcode::kMetadata) ||
        !parseMetadata(ByteCursor(record_buffer_.data() + kRecordPrefixSize,
                                  record_buffer_.size() - kRecordPrefixSize),
                       &m)) {
      warn("metadata index points to no Metadata record", index.offset);
      return false;
    }
    metadata_.push_back(std::move(m));
  }
  return true;
}

void Reader::discardSummary() {
  clearIndex();
  data_end_ = file_.size() - kMagicSize - kFooterRecordSize;
}

}  // namespace deepnav::mcap
