#include <algorithm>

#include "drivers/mcap/diagnostic_text.h"
#include "drivers/mcap/format.h"
#include "drivers/mcap/reader.h"

// The data section walked record by record: for readAll() and, for a file without a summary (cut
// off by a crash, or a writer that wrote none), at open() to index its chunks and rebuild its
// statistics. A walk that meets the cut stops at the last complete record.
namespace deepnav::mcap {
namespace {

// Enough of a Chunk record to index it without reading its payload (the compression name is short).
constexpr uint64_t kChunkPrefixScanBytes = kChunkFixedSize + 4 + 256 + 8;
constexpr size_t kMessageIndexPrefixSize = 2 + 4;

}  // namespace

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

}  // namespace deepnav::mcap
