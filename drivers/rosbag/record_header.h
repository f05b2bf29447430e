#pragma once
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

// A bag record's framing and header (Bags/Format/2.0, "Records" and "Headers"): the record is
// <header_len u32><header><data_len u32><data>; the header is a sequence of
// <field_len u32><name>=<value>, fields in any order, values binary. Every length is checked
// against the bytes given: a corrupted length never makes the reader look outside them.
namespace deepnav::rosbag {

// Where a record's parts lie, relative to the start of the buffer (or file) it was framed in.
struct RecordFrame {
  uint64_t offset = 0;         // first byte of header_len
  uint32_t header_len = 0;
  uint32_t data_len = 0;
  uint64_t header_offset = 0;  // offset + 4
  uint64_t data_offset = 0;    // header_offset + header_len + 4
  uint64_t end() const { return data_offset + data_len; }
};

enum class FrameStatus {
  kOk,
  kEnd,        // no byte left: the buffer ends exactly here
  kTruncated,  // a length runs past the end of the bytes available
};

// Frames the record at `pos` of buf[0, size).
FrameStatus frameRecord(const uint8_t* buf, size_t size, uint64_t pos, RecordFrame* frame);

class RecordHeader {
 public:
  // Splits `size` header bytes into fields. False with *what on a field length past the header or
  // a field without '='.
  bool parse(const uint8_t* data, size_t size, std::string* what);

  bool has(std::string_view name) const;
  // The record's op; false when the field is missing or not one byte.
  bool op(uint8_t* op, std::string* what) const;
  // Typed fields: false with *what ("field 'conn' is missing", "field 'time' has 3 bytes, expected
  // 8") when the field is absent or of the wrong size.
  bool u32(std::string_view name, uint32_t* v, std::string* what) const;
  bool u64(std::string_view name, uint64_t* v, std::string* what) const;
  bool timeNs(std::string_view name, int64_t* ns, std::string* what) const;  // uint32 sec, uint32 nsec
  bool string(std::string_view name, std::string* v, std::string* what) const;

 private:
  bool fixed(std::string_view name, size_t size, std::string_view* v, std::string* what) const;
  bool find(std::string_view name, std::string_view* v) const;

  std::vector<std::pair<std::string_view, std::string_view>> fields_;
};

}  // namespace deepnav::rosbag
