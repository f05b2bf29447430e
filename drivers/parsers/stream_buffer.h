#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

namespace deepnav {

// Fixed-capacity byte window over a byte stream, allocated once by init(). Bytes are appended at the
// back and consumed from the front; offset() is the stream offset of the first byte held, so every
// framer can report where in the stream (or file) a bad frame started.
class StreamBuffer {
 public:
  bool init(size_t capacity);
  // Appends up to n bytes; returns how many fitted (fewer when the window is full).
  size_t append(const uint8_t* data, size_t n);
  void consume(size_t n);
  const uint8_t* data() const { return buf_.data() + begin_; }
  size_t size() const { return end_ - begin_; }
  size_t capacity() const { return buf_.size(); }
  bool full() const { return size() == capacity(); }
  uint64_t offset() const { return offset_; }
  void clear();

 private:
  std::vector<uint8_t> buf_;
  size_t begin_ = 0;
  size_t end_ = 0;
  uint64_t offset_ = 0;
};

}  // namespace deepnav
