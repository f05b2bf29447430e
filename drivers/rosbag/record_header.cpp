#include "drivers/rosbag/record_header.h"

#include <cstring>

#include "drivers/rosbag/bag_format.h"

namespace deepnav::rosbag {
namespace {

uint64_t readLe(const uint8_t* p, size_t n) {
  uint64_t x = 0;
  for (size_t i = 0; i < n; ++i) x |= uint64_t(p[i]) << (8 * i);
  return x;
}

}  // namespace

FrameStatus frameRecord(const uint8_t* buf, size_t size, uint64_t pos, RecordFrame* frame) {
  if (pos == size) return FrameStatus::kEnd;
  if (pos > size || size - pos < 4) return FrameStatus::kTruncated;
  RecordFrame f;
  f.offset = pos;
  f.header_len = uint32_t(readLe(buf + pos, 4));
  f.header_offset = pos + 4;
  if (size - f.header_offset < uint64_t(f.header_len) + 4) return FrameStatus::kTruncated;
  f.data_len = uint32_t(readLe(buf + f.header_offset + f.header_len, 4));
  f.data_offset = f.header_offset + f.header_len + 4;
  if (size - f.data_offset < f.data_len) return FrameStatus::kTruncated;
  *frame = f;
  return FrameStatus::kOk;
}

bool RecordHeader::parse(const uint8_t* data, size_t size, std::string* what) {
  fields_.clear();
  size_t pos = 0;
  while (pos < size) {
    if (size - pos < 4) {
      *what = "header field length cut off at header byte " + std::to_string(pos);
      return false;
    }
    const uint64_t n = readLe(data + pos, 4);
    pos += 4;
    if (n > size - pos) {
      *what = "header field at header byte " + std::to_string(pos - 4) + " is " + std::to_string(n) +
              " bytes long, past the header's end (" + std::to_string(size) + " bytes)";
      return false;
    }
    const char* field = reinterpret_cast<const char*>(data + pos);
    const void* eq = std::memchr(field, '=', size_t(n));
    if (eq == nullptr) {
      *what = "header field at header byte " + std::to_string(pos - 4) + " has no '='";
      return false;
    }
    const size_t name_len = size_t(static_cast<const char*>(eq) - field);
    fields_.emplace_back(std::string_view(field, name_len),
                         std::string_view(field + name_len + 1, size_t(n) - name_len - 1));
    pos += size_t(n);
  }
  return true;
}

bool RecordHeader::find(std::string_view name, std::string_view* v) const {
  for (const auto& [field, value] : fields_) {
    if (field == name) {
      *v = value;
      return true;
    }
  }
  return false;
}

bool RecordHeader::has(std::string_view name) const {
  std::string_view ignored;
  return find(name, &ignored);
}

bool RecordHeader::fixed(std::string_view name, size_t size, std::string_view* v,
                         std::string* what) const {
  if (!find(name, v)) {
    *what = "header field '" + std::string(name) + "' is missing";
    return false;
  }
  if (v->size() != size) {
    *what = "header field '" + std::string(name) + "' has " + std::to_string(v->size()) +
            " bytes, expected " + std::to_string(size);
    return false;
  }
  return true;
}

bool RecordHeader::op(uint8_t* op, std::string* what) const {
  std::string_view v;
  if (!fixed("op", 1, &v, what)) return false;
  *op = uint8_t(v[0]);
  return true;
}

bool RecordHeader::u32(std::string_view name, uint32_t* v, std::string* what) const {
  std::string_view s;
  if (!fixed(name, 4, &s, what)) return false;
  *v = uint32_t(readLe(reinterpret_cast<const uint8_t*>(s.data()), 4));
  return true;
}

bool RecordHeader::u64(std::string_view name, uint64_t* v, std::string* what) const {
  std::string_view s;
  if (!fixed(name, 8, &s, what)) return false;
  *v = readLe(reinterpret_cast<const uint8_t*>(s.data()), 8);
  return true;
}

bool RecordHeader::timeNs(std::string_view name, int64_t* ns, std::string* what) const {
  std::string_view s;
  if (!fixed(name, 8, &s, what)) return false;
  const auto* p = reinterpret_cast<const uint8_t*>(s.data());
  const auto sec = uint32_t(readLe(p, 4));
  const auto nsec = uint32_t(readLe(p + 4, 4));
  if (nsec >= 1000000000u) {
    *what = "header field '" + std::string(name) + "' has " + std::to_string(nsec) +
            " nanoseconds, expected less than 1e9";
    return false;
  }
  *ns = rosTimeNs(sec, nsec);
  return true;
}

bool RecordHeader::string(std::string_view name, std::string* v, std::string* what) const {
  std::string_view s;
  if (!find(name, &s)) {
    *what = "header field '" + std::string(name) + "' is missing";
    return false;
  }
  v->assign(s);
  return true;
}

}  // namespace deepnav::rosbag
