#include "drivers/parsers/stream_buffer.h"

#include <algorithm>
#include <cstring>

namespace deepnav {

bool StreamBuffer::init(size_t capacity) {
  if (capacity == 0) return false;
  buf_.assign(capacity, 0);
  begin_ = end_ = 0;
  offset_ = 0;
  return true;
}

size_t StreamBuffer::append(const uint8_t* data, size_t n) {
  if (end_ + n > buf_.size() && begin_ > 0) {  // compact: move the unread bytes to the front
    std::memmove(buf_.data(), buf_.data() + begin_, size());
    end_ -= begin_;
    begin_ = 0;
  }
  const size_t take = std::min(n, buf_.size() - end_);
  if (take > 0) std::memcpy(buf_.data() + end_, data, take);
  end_ += take;
  return take;
}

void StreamBuffer::consume(size_t n) {
  n = std::min(n, size());
  begin_ += n;
  offset_ += n;
  if (begin_ == end_) begin_ = end_ = 0;
}

void StreamBuffer::clear() { consume(size()); }

}  // namespace deepnav
