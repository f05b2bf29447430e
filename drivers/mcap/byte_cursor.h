#pragma once
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

// Bounds-checked little-endian reading of MCAP fields from a byte range. Every getter returns
// false, and leaves the output untouched, when the field would run past the end: a corrupted
// length can never make the reader look outside the bytes it was given.
namespace deepnav::mcap {

class ByteCursor {
 public:
  ByteCursor(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  size_t offset() const { return pos_; }
  size_t remaining() const { return size_ - pos_; }
  const uint8_t* here() const { return data_ + pos_; }

  bool u8(uint8_t* v) { return le(v, 1); }
  bool u16(uint16_t* v) { return le(v, 2); }
  bool u32(uint32_t* v) { return le(v, 4); }
  bool u64(uint64_t* v) { return le(v, 8); }

  // `n` raw bytes; *p points into the cursor's range.
  bool bytes(uint64_t n, const uint8_t** p);
  bool skip(uint64_t n);
  // MCAP String: uint32 length + bytes.
  bool stringView(std::string_view* s);
  bool string(std::string* s);
  // uint32-length-prefixed block (Map, Array): a sub-cursor over exactly its entries.
  bool block(ByteCursor* inner);
  bool stringMap(std::map<std::string, std::string>* m);

 private:
  template <typename T>
  bool le(T* v, size_t n) {
    if (remaining() < n) return false;
    uint64_t x = 0;
    for (size_t i = 0; i < n; ++i) x |= uint64_t(data_[pos_ + i]) << (8 * i);
    *v = T(x);
    pos_ += n;
    return true;
  }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

}  // namespace deepnav::mcap
