#include "drivers/cdr/cdr_reader.h"

#include <bit>
#include <cstring>

#include "drivers/cdr/cdr_writer.h"

namespace deepnav::cdr {

static_assert(std::endian::native == std::endian::little,
              "CdrReader copies primitives as they are in memory: little-endian hosts only");

CdrReader::CdrReader(const uint8_t* data, size_t size) : data_(data), size_(size) {
  // Byte 1 is the representation id: 0x01 = CDR_LE. Bytes 2-3 are options, ignored.
  ok_ = size >= kEncapsulationSize && data[0] == 0x00 && data[1] == 0x01;
  pos_ = ok_ ? kEncapsulationSize : 0;
}

bool CdrReader::align(size_t n) {
  const size_t misalignment = (pos_ - kEncapsulationSize) % n;
  if (!ok_ || misalignment == 0) return ok_;
  if (n - misalignment > size_ - pos_) return ok_ = false;
  pos_ += n - misalignment;
  return true;
}

bool CdrReader::raw(void* out, size_t n) {
  if (!ok_ || n > size_ - pos_) return ok_ = false;
  if (n > 0) std::memcpy(out, data_ + pos_, n);
  pos_ += n;
  return true;
}

bool CdrReader::boolean(bool* v) {
  uint8_t b = 0;
  if (!u8(&b)) return false;
  if (b > 1) return ok_ = false;
  *v = b != 0;
  return true;
}

bool CdrReader::string(std::string* s) {
  uint32_t n = 0;
  if (!u32(&n)) return false;
  if (n == 0 || n > size_ - pos_ || data_[pos_ + n - 1] != 0) return ok_ = false;
  s->assign(reinterpret_cast<const char*>(data_ + pos_), n - 1);
  pos_ += n;
  return true;
}

bool CdrReader::sequenceLength(uint32_t* count, size_t min_element_bytes) {
  uint32_t n = 0;
  if (!u32(&n)) return false;
  if (min_element_bytes > 0 && n > (size_ - pos_) / min_element_bytes) return ok_ = false;
  *count = n;
  return true;
}

bool CdrReader::u8Array(uint8_t* out, size_t count) { return raw(out, count); }

bool CdrReader::f64Array(double* out, size_t count) {
  if (count == 0) return ok_;
  return align(8) && raw(out, count * sizeof(double));
}

bool CdrReader::u8SequenceView(const uint8_t** data, size_t* count) {
  uint32_t n = 0;
  if (!sequenceLength(&n, 1)) return false;
  *data = data_ + pos_;
  *count = n;
  pos_ += n;
  return true;
}

}  // namespace deepnav::cdr
