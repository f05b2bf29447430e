#include "drivers/mcap/reader.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <queue>

#include "drivers/mcap/crc32.h"
#include "drivers/mcap/format.h"

namespace deepnav::mcap {
namespace {

// A corrupt uncompressed_size must not make the reader allocate without bound.
constexpr uint64_t kMaxChunkUncompressedBytes = uint64_t(1) << 30;
// Enough of a Chunk record to index it without reading its payload (the compression name is short).
constexpr uint64_t kChunkPrefixScanBytes = kChunkFixedSize + 4 + 256 + 8;
constexpr size_t kMessageIndexPrefixSize = 2 + 4;

uint64_t le64(const uint8_t* p) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[i];
  return v;
}

std::string secondsText(uint64_t ns) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%llu.%09llu",
                static_cast<unsigned long long>(ns / 1'000'000'000),
                static_cast<unsigned long long>(ns % 1'000'000'000));
  return buf;
}

std::string hex32(uint32_t v) {
  char buf[16];
  std::snprintf(buf, sizeof(buf), "0x%08X", v);
  return buf;
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Opening: header, footer, summary -- or a scan of the data section when there is no summary.

void Reader::reset() {
  file_.close();
  path_.clear();
  header_ = Header{};
  schemas_.clear();
  channels_.clear();
  statistics_ = Statistics{};
  chunks_.clear();
  metadata_.clear();
  has_summary_ = footer_valid_ = truncated_ = has_unchunked_messages_ = false;
  data_start_ = data_end_ = 0;
  header_crc_ = data_crc_ = 0;
  scanned_channel_counts_.clear();
  scanned_any_time_ = false;
  scanned_start_ns_ = scanned_end_ns_ = 0;
  walk_end_ = 0;
  skipped_chunks_ = 0;
  warnings_.clear();
  error_.clear();
  cut_reason_.clear();
}

void Reader::close() { reset(); }

bool Reader::fail(const std::string& what, uint64_t offset) {
  error_ = path_ + ": " + what + " at byte " + std::to_string(offset);
  return false;
}

void Reader::warn(const std::string& what, uint64_t offset) {
  warnings_.push_back(path_ + ": " + what + " at byte " + std::to_string(offset));
}

const Schema* Reader::schema(uint16_t id) const {
  const auto it = schemas_.find(id);
  return it == schemas_.end() ? nullptr : &it->second;
}

const Channel* Reader::channel(uint16_t id) const {
  const auto it = channels_.find(id);
  return it == channels_.end() ? nullptr : &it->second;
}

bool Reader::open(const std::string& path, std::string* error) {
  reset();
  path_ = path;
  bool ok = file_.open(path, &error_) && readMagicAndHeader();
  if (ok) {
    Footer footer;
    footer_valid_ = readFooter(&footer);
    data_end_ = footer_valid_ ? file_.size() - kMagicSize - kFooterRecordSize : file_.size();
    if (footer_valid_ && footer.summary_start != 0 && !loadSummary(footer)) discardSummary();
    if (!has_summary_) ok = scanDataSection();
  }
  if (!ok) {
    *error = error_;
    file_.close();
  }
  return ok;
}

bool Reader::readMagicAndHeader() {
  uint8_t magic[kMagicSize];
  if (!file_.readAt(0, kMagicSize, magic) || std::memcmp(magic, kMagic, kMagicSize) != 0) {
    return fail("not an MCAP file (no MCAP magic)", 0);
  }
  uint8_t prefix[kRecordPrefixSize];
  if (!file_.readAt(kMagicSize, kRecordPrefixSize, prefix)) {
    return fail("file ends inside the Header record", kMagicSize);
  }
  if (prefix[0] != uint8_t(Opcode::kHeader)) {
    return fail("expected a Header record, found " + opcodeName(prefix[0]), kMagicSize);
  }
  const uint64_t length = le64(prefix + 1);
  const uint64_t content_at = kMagicSize + kRecordPrefixSize;
  if (length > file_.size() - content_at) {
    return fail("file ends inside the Header record (" + std::to_string(length) + " bytes)",
                kMagicSize);
  }
  if (!readContent(content_at, length, &record_buffer_) ||
      !parseHeader(ByteCursor(record_buffer_.data(), record_buffer_.size()), &header_)) {
    return fail("malformed Header record", kMagicSize);
  }
  data_start_ = content_at + length;
  header_crc_ = crc32Update(crc32Update(crc32(magic, kMagicSize), prefix, kRecordPrefixSize),
                            record_buffer_.data(), record_buffer_.size());
  return true;
}

bool Reader::readFooter(Footer* footer) {
  const uint64_t size = file_.size();
  uint8_t tail[kFooterRecordSize + kMagicSize];
  if (size < data_start_ + sizeof(tail) || !file_.readAt(size - sizeof(tail), sizeof(tail), tail)) {
    return false;
  }
  if (std::memcmp(tail + kFooterRecordSize, kMagic, kMagicSize) != 0) return false;
  if (tail[0] != uint8_t(Opcode::kFooter) || le64(tail + 1) != kFooterContentSize) {
    warn("trailing magic present but no valid Footer record before it", size - sizeof(tail));
    return false;
  }
  return parseFooter(ByteCursor(tail + kRecordPrefixSize, kFooterContentSize), footer);
}

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
  schemas_.clear();
  channels_.clear();
  statistics_ = Statistics{};
  chunks_.clear();
  metadata_.clear();
  has_summary_ = false;
  data_end_ = file_.size() - kMagicSize - kFooterRecordSize;
}

bool Reader::scanDataSection() {
  const bool ok = walkDataSection([this](uint64_t offset, uint8_t op, uint64_t length) {
    return scanRecord(offset, op, length);
  });
  if (!ok) return false;
  if (!footer_valid_) {
    // No footer: whatever the scan reached is all a reader may trust.
    truncated_ = true;
    data_end_ = walk_end_;
    if (cut_reason_.empty())
      cut_reason_ = "no summary or footer after byte " + std::to_string(walk_end_);
  }
  rebuildStatistics();
  if (truncated_) describeCut();
  return true;
}

Reader::Visit Reader::scanRecord(uint64_t offset, uint8_t op, uint64_t length) {
  const auto malformed = [&]() {
    const std::string what = "malformed " + opcodeName(op) + " record";
    if (footer_valid_) {
      fail(what, offset);
      return Visit::kError;
    }
    cut_reason_ = what + " at byte " + std::to_string(offset);
    walk_end_ = offset;
    return Visit::kStop;
  };
  switch (Opcode(op)) {
    case Opcode::kSchema:
    case Opcode::kChannel:
      if (!readContent(offset + kRecordPrefixSize, length, &record_buffer_) ||
          !definitionRecord(op, record_buffer_.data(), record_buffer_.size(), offset)) {
        return malformed();
      }
      return Visit::kContinue;
    case Opcode::kMetadata: {
      Metadata m;
      if (!readContent(offset + kRecordPrefixSize, length, &record_buffer_) ||
          !parseMetadata(ByteCursor(record_buffer_.data(), record_buffer_.size()), &m)) {
        return malformed();
      }
      metadata_.push_back(std::move(m));
      return Visit::kContinue;
    }
    case Opcode::kChunk:
      return scanChunk(offset, length) ? Visit::kContinue : malformed();
    case Opcode::kMessageIndex:
      return scanMessageIndex(offset, length) ? Visit::kContinue : malformed();
    case Opcode::kMessage:
      return scanUnchunkedMessage(offset, length) ? Visit::kContinue : malformed();
    case Opcode::kDataEnd:
      return Visit::kStop;
    default:
      return Visit::kContinue;
  }
}

bool Reader::scanChunk(uint64_t offset, uint64_t length) {
  const uint64_t n = std::min(length, kChunkPrefixScanBytes);
  ChunkView view;
  if (!readContent(offset + kRecordPrefixSize, n, &record_buffer_) ||
      !parseChunkPrefix(ByteCursor(record_buffer_.data(), record_buffer_.size()), &view)) {
    return false;
  }
  const uint64_t prefix_size = kChunkFixedSize + 4 + view.compression.size() + 8;
  if (view.records_size > length - prefix_size) return false;
  ChunkInfo info;
  info.message_start_time_ns = view.message_start_time_ns;
  info.message_end_time_ns = view.message_end_time_ns;
  info.chunk_start_offset = offset;
  info.chunk_length = kRecordPrefixSize + length;
  info.compression = view.compression;
  info.compressed_size = view.records_size;
  info.uncompressed_size = view.uncompressed_size;
  chunks_.push_back(std::move(info));
  return true;
}

bool Reader::scanMessageIndex(uint64_t offset, uint64_t length) {
  uint16_t channel_id = 0;
  uint64_t count = 0;
  if (length < kMessageIndexPrefixSize ||
      !readContent(offset + kRecordPrefixSize, kMessageIndexPrefixSize, &record_buffer_)) {
    return false;
  }
  // The cursor only holds the prefix; check the array length against the whole record here.
  ByteCursor c(record_buffer_.data(), record_buffer_.size());
  uint32_t array_bytes = 0;
  if (!c.u16(&channel_id) || !c.u32(&array_bytes) || array_bytes % 16 != 0 ||
      array_bytes > length - kMessageIndexPrefixSize) {
    return false;
  }
  count = array_bytes / 16;
  scanned_channel_counts_[channel_id] += count;
  if (!chunks_.empty()) chunks_.back().message_index_length += kRecordPrefixSize + length;
  return true;
}

bool Reader::scanUnchunkedMessage(uint64_t offset, uint64_t length) {
  MessageView m;
  if (length < kMessageFixedSize ||
      !readContent(offset + kRecordPrefixSize, kMessageFixedSize, &record_buffer_) ||
      !parseMessage(ByteCursor(record_buffer_.data(), record_buffer_.size()), &m)) {
    return false;
  }
  has_unchunked_messages_ = true;
  ++scanned_channel_counts_[m.channel_id];
  noteScannedTime(m.log_time_ns);
  return true;
}

void Reader::noteScannedTime(uint64_t t_ns) {
  if (!scanned_any_time_) {
    scanned_start_ns_ = scanned_end_ns_ = t_ns;
    scanned_any_time_ = true;
  }
  scanned_start_ns_ = std::min(scanned_start_ns_, t_ns);
  scanned_end_ns_ = std::max(scanned_end_ns_, t_ns);
}

void Reader::rebuildStatistics() {
  Statistics s;
  s.schema_count = uint16_t(schemas_.size());
  s.channel_count = uint32_t(channels_.size());
  s.metadata_count = uint32_t(metadata_.size());
  s.chunk_count = uint32_t(chunks_.size());
  s.channel_message_counts = scanned_channel_counts_;
  for (const auto& [id, count] : scanned_channel_counts_) s.message_count += count;
  for (const ChunkInfo& c : chunks_) {
    if (c.uncompressed_size == 0) continue;
    noteScannedTime(c.message_start_time_ns);
    noteScannedTime(c.message_end_time_ns);
  }
  s.message_start_time_ns = scanned_any_time_ ? scanned_start_ns_ : 0;
  s.message_end_time_ns = scanned_any_time_ ? scanned_end_ns_ : 0;
  statistics_ = std::move(s);
}

void Reader::describeCut() {
  std::string text = "recording " + path_ + " cut off after " + std::to_string(chunks_.size()) +
                     " complete chunks (" + cut_reason_ + ")";
  text += scanned_any_time_ ? "; last message at t=" + secondsText(scanned_end_ns_) + " s"
                            : "; no complete message";
  warnings_.push_back(std::move(text));
}

// ---------------------------------------------------------------------------------------------
// Walking the data section record by record.

bool Reader::walkDataSection(const RecordVisitor& visit) {
  uint64_t offset = data_start_;
  uint8_t prefix[kRecordPrefixSize];
  while (offset < data_end_) {
    if (data_end_ - offset < kRecordPrefixSize ||
        !file_.readAt(offset, kRecordPrefixSize, prefix)) {
      return cutOff(offset, "file ends inside a record prefix at byte " + std::to_string(offset));
    }
    const uint8_t op = prefix[0];
    const uint64_t length = le64(prefix + 1);
    if (op == 0)
      return cutOff(offset, "zero bytes instead of a record at byte " + std::to_string(offset));
    if (length > data_end_ - offset - kRecordPrefixSize) {
      return cutOff(offset, "file ends inside a " + opcodeName(op) + " record of " +
                                std::to_string(length) + " bytes starting at byte " +
                                std::to_string(offset));
    }
    walk_end_ = offset + kRecordPrefixSize + length;
    switch (visit(offset, op, length)) {
      case Visit::kError:
        return false;
      case Visit::kStop:
        return true;
      case Visit::kContinue:
        break;
    }
    offset += kRecordPrefixSize + length;
  }
  walk_end_ = offset;
  return true;
}

bool Reader::cutOff(uint64_t offset, const std::string& why) {
  walk_end_ = offset;
  if (footer_valid_) {
    const std::string where = "data section ends at byte " + std::to_string(data_end_);
    return fail(why + ", but the " + where, offset);
  }
  cut_reason_ = why;
  return true;
}

bool Reader::readContent(uint64_t offset, uint64_t length, std::vector<uint8_t>* out) {
  if (length > file_.size()) return false;
  out->resize(size_t(length));
  return file_.readAt(offset, size_t(length), out->data());
}

bool Reader::definitionRecord(uint8_t opcode, const uint8_t* content, size_t size, uint64_t) {
  const ByteCursor c(content, size);
  if (opcode == uint8_t(Opcode::kSchema)) {
    Schema s;
    if (!parseSchema(c, &s)) return false;
    if (s.id != 0 && schemas_.count(s.id) == 0) schemas_.emplace(s.id, std::move(s));
    return true;
  }
  Channel ch;
  if (!parseChannel(c, &ch)) return false;
  if (channels_.count(ch.id) == 0) channels_.emplace(ch.id, std::move(ch));
  return true;
}

// ---------------------------------------------------------------------------------------------
// Reading messages in file order.

bool Reader::readAll(const MessageCallback& callback) {
  if (data_start_ == 0) {
    error_ = "mcap reader: no file open";
    return false;
  }
  error_.clear();
  data_crc_ = header_crc_;
  return walkDataSection([&](uint64_t offset, uint8_t op, uint64_t length) {
    return readAllRecord(offset, op, length, callback);
  });
}

Reader::Visit Reader::readAllRecord(uint64_t offset, uint8_t op, uint64_t length,
                                    const MessageCallback& callback) {
  if (!readContent(offset + kRecordPrefixSize, length, &record_buffer_)) {
    fail("read error in " + opcodeName(op) + " record", offset);
    return Visit::kError;
  }
  const uint8_t* content = record_buffer_.data();
  const size_t size = record_buffer_.size();
  if (op == uint8_t(Opcode::kDataEnd)) {
    checkDataCrc(content, size, offset);
    return Visit::kStop;
  }
  uint8_t prefix[kRecordPrefixSize] = {op};
  for (size_t i = 0; i < 8; ++i) prefix[1 + i] = uint8_t(length >> (8 * i));
  data_crc_ = crc32Update(crc32Update(data_crc_, prefix, sizeof(prefix)), content, size);

  bool ok = true;
  if (op == uint8_t(Opcode::kSchema) || op == uint8_t(Opcode::kChannel)) {
    ok = definitionRecord(op, content, size, offset);
  } else if (op == uint8_t(Opcode::kMessage)) {
    MessageView m;
    ok = parseMessage(ByteCursor(content, size), &m);
    if (ok) callback(m);
  } else if (op == uint8_t(Opcode::kChunk)) {
    if (!deliverChunk(content, size, offset, callback)) return Visit::kError;
  }
  if (!ok) {
    fail("malformed " + opcodeName(op) + " record", offset);
    return Visit::kError;
  }
  return Visit::kContinue;
}

void Reader::checkDataCrc(const uint8_t* content, size_t size, uint64_t offset) {
  uint32_t expected = 0;
  if (!parseDataEnd(ByteCursor(content, size), &expected)) {
    warn("malformed DataEnd record", offset);
  } else if (expected != 0 && expected != data_crc_) {
    warn("data section CRC mismatch (DataEnd says " + hex32(expected) + ", computed " +
             hex32(data_crc_) + "): some byte before the DataEnd record is damaged",
         offset);
  }
}

Reader::Unpack Reader::unpackChunk(const uint8_t* content, size_t size, uint64_t offset,
                                   const uint8_t** records, size_t* records_size) {
  ChunkView v;
  if (!parseChunk(ByteCursor(content, size), &v)) {
    fail("malformed Chunk record", offset);
    return Unpack::kFatal;
  }
  const auto skip = [&](const std::string& why) {
    ++skipped_chunks_;
    warn("chunk skipped: " + why, offset);
    return Unpack::kSkipped;
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
  return Unpack::kOk;
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

bool Reader::deliverChunk(const uint8_t* content, size_t size, uint64_t offset,
                          const MessageCallback& callback) {
  const uint8_t* records = nullptr;
  size_t records_size = 0;
  switch (unpackChunk(content, size, offset, &records, &records_size)) {
    case Unpack::kFatal:
      return false;
    case Unpack::kSkipped:
      return true;
    case Unpack::kOk:
      break;
  }
  forEachChunkRecord(records, records_size, offset,
                     [&](uint8_t op, const uint8_t* c, size_t n, uint64_t) {
                       if (op == uint8_t(Opcode::kMessage)) {
                         MessageView m;
                         if (!parseMessage(ByteCursor(c, n), &m)) return false;
                         callback(m);
                         return true;
                       }
                       if (op == uint8_t(Opcode::kSchema) || op == uint8_t(Opcode::kChannel)) {
                         return definitionRecord(op, c, n, offset);
                       }
                       return true;
                     });
  return true;
}

// ---------------------------------------------------------------------------------------------
// Reading messages in log-time order: a k-way merge over chunks sorted by start time.

bool Reader::loadChunkAt(const ChunkInfo& chunk, std::vector<uint8_t>* records) {
  records->clear();
  if (!chunkInfoInBounds(chunk) ||
      !readContent(chunk.chunk_start_offset, chunk.chunk_length, &record_buffer_) ||
      record_buffer_[0] != uint8_t(Opcode::kChunk) ||
      le64(record_buffer_.data() + 1) != chunk.chunk_length - kRecordPrefixSize) {
    return fail("chunk index points to no Chunk record", chunk.chunk_start_offset);
  }
  const uint8_t* data = nullptr;
  size_t size = 0;
  switch (unpackChunk(record_buffer_.data() + kRecordPrefixSize,
                      record_buffer_.size() - kRecordPrefixSize, chunk.chunk_start_offset, &data,
                      &size)) {
    case Unpack::kFatal:
      return false;
    case Unpack::kSkipped:
      return true;
    case Unpack::kOk:
      break;
  }
  records->assign(data, data + size);
  return true;
}

// Messages of the decompressed chunks not yet delivered, earliest log time on top. Each chunk's
// records live in a slot until its last message is out.
struct Reader::LogTimeMerge {
  struct Pending {
    uint64_t log_time_ns;
    uint64_t chunk_offset;  // ties in log time go in file order
    size_t content_at;      // Message content inside the slot's records
    size_t content_size;
    size_t slot;
  };
  struct Later {
    bool operator()(const Pending& a, const Pending& b) const {
      if (a.log_time_ns != b.log_time_ns) return a.log_time_ns > b.log_time_ns;
      if (a.chunk_offset != b.chunk_offset) return a.chunk_offset > b.chunk_offset;
      return a.content_at > b.content_at;
    }
  };

  size_t takeSlot() {
    if (!free_slots.empty()) {
      const size_t slot = free_slots.back();
      free_slots.pop_back();
      return slot;
    }
    slots.emplace_back();
    remaining.push_back(0);
    return slots.size() - 1;
  }

  std::priority_queue<Pending, std::vector<Pending>, Later> heap;
  std::vector<std::vector<uint8_t>> slots;
  std::vector<size_t> remaining;
  std::vector<size_t> free_slots;
};

bool Reader::mergeChunk(const ChunkInfo& chunk, LogTimeMerge* merge) {
  const size_t slot = merge->takeSlot();
  if (!loadChunkAt(chunk, &merge->slots[slot])) return false;
  const std::vector<uint8_t>& records = merge->slots[slot];
  forEachChunkRecord(records.data(), records.size(), chunk.chunk_start_offset,
                     [&](uint8_t op, const uint8_t* content, size_t size, uint64_t at) {
                       if (op == uint8_t(Opcode::kSchema) || op == uint8_t(Opcode::kChannel)) {
                         return definitionRecord(op, content, size, chunk.chunk_start_offset);
                       }
                       if (op != uint8_t(Opcode::kMessage)) return true;
                       MessageView m;
                       if (!parseMessage(ByteCursor(content, size), &m)) return false;
                       merge->heap.push({m.log_time_ns, chunk.chunk_start_offset,
                                         size_t(at) + kRecordPrefixSize, size, slot});
                       ++merge->remaining[slot];
                       return true;
                     });
  if (merge->remaining[slot] == 0) merge->free_slots.push_back(slot);
  return true;
}

bool Reader::readAllInLogTimeOrder(const MessageCallback& callback) {
  if (data_start_ == 0) {
    error_ = "mcap reader: no file open";
    return false;
  }
  if (has_unchunked_messages_) return readAllSortedInMemory(callback);
  error_.clear();
  std::vector<ChunkInfo> order = chunks_;
  std::sort(order.begin(), order.end(), [](const ChunkInfo& a, const ChunkInfo& b) {
    if (a.message_start_time_ns != b.message_start_time_ns) {
      return a.message_start_time_ns < b.message_start_time_ns;
    }
    return a.chunk_start_offset < b.chunk_start_offset;
  });
  LogTimeMerge merge;
  size_t next = 0;
  while (!merge.heap.empty() || next < order.size()) {
    // A chunk starting no later than the earliest pending message may hold an earlier one.
    if (next < order.size() &&
        (merge.heap.empty() || order[next].message_start_time_ns <= merge.heap.top().log_time_ns)) {
      if (!mergeChunk(order[next++], &merge)) return false;
      continue;
    }
    const LogTimeMerge::Pending p = merge.heap.top();
    merge.heap.pop();
    MessageView m;
    parseMessage(ByteCursor(merge.slots[p.slot].data() + p.content_at, p.content_size), &m);
    callback(m);
    if (--merge.remaining[p.slot] == 0) merge.free_slots.push_back(p.slot);
  }
  return true;
}

// Files with messages outside chunks (not ours) have no chunk order to merge; sort them all.
bool Reader::readAllSortedInMemory(const MessageCallback& callback) {
  struct Copy {
    MessageView view;
    size_t data_at;
  };
  std::vector<Copy> copies;
  std::vector<uint8_t> bytes;
  const bool ok = readAll([&](const MessageView& m) {
    copies.push_back(Copy{m, bytes.size()});
    bytes.insert(bytes.end(), m.data, m.data + m.size);
  });
  std::stable_sort(copies.begin(), copies.end(), [](const Copy& a, const Copy& b) {
    return a.view.log_time_ns < b.view.log_time_ns;
  });
  for (Copy& c : copies) {
    c.view.data = bytes.data() + c.data_at;
    callback(c.view);
  }
  return ok;
}

}  // namespace deepnav::mcap
