#include "drivers/mcap/byte_cursor.h"

namespace deepnav::mcap {

bool ByteCursor::bytes(uint64_t n, const uint8_t** p) {
  if (n > remaining()) return false;
  *p = data_ + pos_;
  pos_ += size_t(n);
  return true;
}

bool ByteCursor::skip(uint64_t n) {
  const uint8_t* ignored = nullptr;
  return bytes(n, &ignored);
}

bool ByteCursor::stringView(std::string_view* s) {
  ByteCursor chars(nullptr, 0);  // a String is laid out as a block of chars
  if (!block(&chars)) return false;
  *s = std::string_view(reinterpret_cast<const char*>(chars.here()), chars.remaining());
  return true;
}

bool ByteCursor::string(std::string* s) {
  std::string_view v;
  if (!stringView(&v)) return false;
  s->assign(v);
  return true;
}

bool ByteCursor::block(ByteCursor* inner) {
  const size_t start = pos_;
  uint32_t n = 0;
  const uint8_t* p = nullptr;
  if (!u32(&n) || !bytes(n, &p)) {
    pos_ = start;
    return false;
  }
  *inner = ByteCursor(p, n);
  return true;
}

bool ByteCursor::stringMap(std::map<std::string, std::string>* m) {
  ByteCursor entries(nullptr, 0);
  if (!block(&entries)) return false;
  std::map<std::string, std::string> result;
  while (entries.remaining() > 0) {
    std::string key, value;
    if (!entries.string(&key) || !entries.string(&value)) return false;
    result[std::move(key)] = std::move(value);
  }
  *m = std::move(result);
  return true;
}

}  // namespace deepnav::mcap
