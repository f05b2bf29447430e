#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

// Bounds-checked reader for the plain little-endian CDR that CdrWriter writes (see cdr_writer.h
// for the layout). Failure is sticky: after the first out-of-range or malformed field every
// getter returns false, so a decoder can read all fields and check ok() once.
namespace deepnav::cdr {

class CdrReader {
 public:
  // Checks the encapsulation header: only CDR_LE (00 01) is accepted.
  CdrReader(const uint8_t* data, size_t size);

  bool boolean(bool* v);
  bool u8(uint8_t* v) { return primitive(v, 1); }
  bool i8(int8_t* v) { return primitive(v, 1); }
  bool u16(uint16_t* v) { return primitive(v, 2); }
  bool i16(int16_t* v) { return primitive(v, 2); }
  bool u32(uint32_t* v) { return primitive(v, 4); }
  bool i32(int32_t* v) { return primitive(v, 4); }
  bool u64(uint64_t* v) { return primitive(v, 8); }
  bool i64(int64_t* v) { return primitive(v, 8); }
  bool f32(float* v) { return primitive(v, 4); }
  bool f64(double* v) { return primitive(v, 8); }
  // Requires the NUL terminator the length counts.
  bool string(std::string* s);
  // Element count of a sequence, refused when `count * min_element_bytes` cannot fit in what is
  // left (a corrupt count must not make the caller allocate gigabytes).
  bool sequenceLength(uint32_t* count, size_t min_element_bytes);
  bool u8Array(uint8_t* out, size_t count);
  bool f64Array(double* out, size_t count);
  // uint8[] sequence without copying: *data points into the input.
  bool u8SequenceView(const uint8_t** data, size_t* count);

  bool ok() const { return ok_; }
  size_t remaining() const { return ok_ ? size_ - pos_ : 0; }

 private:
  bool align(size_t n);
  bool raw(void* out, size_t n);
  bool primitive(void* v, size_t n) { return align(n) && raw(v, n); }

  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  bool ok_ = true;
};

}  // namespace deepnav::cdr
