#include "drivers/rosbag/bag_file.h"

#include <algorithm>

namespace deepnav::rosbag {
namespace {

// Record headers hold a few short fields; a larger header_len is corruption, not data.
constexpr uint32_t kMaxHeaderBytes = 1u << 20;

uint32_t le32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

}  // namespace

bool BagFile::open(const std::string& path, std::string* error) {
  path_ = path;
  return file_.open(path, error);
}

ReadStatus BagFile::readRecord(uint64_t pos, uint64_t limit, RecordFrame* frame,
                               RecordHeader* header, std::string* what) {
  limit = std::min(limit, file_.size());
  if (pos >= limit) return pos == limit ? ReadStatus::kEnd : ReadStatus::kHeaderCut;
  uint8_t len[4];
  if (limit - pos < 4 || !file_.readAt(pos, 4, len)) return ReadStatus::kHeaderCut;
  RecordFrame f;
  f.offset = pos;
  f.header_len = le32(len);
  f.header_offset = pos + 4;
  if (limit - f.header_offset < uint64_t(f.header_len) + 4) return ReadStatus::kHeaderCut;
  if (f.header_len > kMaxHeaderBytes) {
    *what = "header_len is " + std::to_string(f.header_len) + " bytes, more than a record header holds";
    return ReadStatus::kBadHeader;
  }
  header_bytes_.resize(f.header_len + 4);
  if (!file_.readAt(f.header_offset, header_bytes_.size(), header_bytes_.data())) {
    return ReadStatus::kHeaderCut;
  }
  f.data_len = le32(header_bytes_.data() + f.header_len);
  f.data_offset = f.header_offset + f.header_len + 4;
  *frame = f;
  if (!header->parse(header_bytes_.data(), f.header_len, what)) return ReadStatus::kBadHeader;
  if (limit - f.data_offset < f.data_len) return ReadStatus::kDataCut;
  return ReadStatus::kOk;
}

bool BagFile::readData(const RecordFrame& frame, uint64_t n, std::vector<uint8_t>* out) const {
  out->resize(size_t(n));
  return n == 0 || file_.readAt(frame.data_offset, size_t(n), out->data());
}

}  // namespace deepnav::rosbag
