#include "drivers/mcap/reader.h"

#include <cstring>

#include "drivers/mcap/crc32.h"
#include "drivers/mcap/format.h"

// Opening a file: the header, then the footer; the summary (reader_summary.cpp) or, without one,
// a scan of the data section (reader_scan.cpp). Reading messages: reader_file_order.cpp and
// reader_log_time_order.cpp, chunk by chunk (reader_chunk.cpp).
namespace deepnav::mcap {

void Reader::reset() {
  file_.close();
  path_.clear();
  header_ = Header{};
  clearIndex();
  footer_valid_ = truncated_ = has_unchunked_messages_ = false;
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

void Reader::clearIndex() {
  schemas_.clear();
  channels_.clear();
  statistics_ = Statistics{};
  chunks_.clear();
  metadata_.clear();
  has_summary_ = false;
}

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

}  // namespace deepnav::mcap
