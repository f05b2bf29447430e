#pragma once
#include <cstddef>
#include <cstdint>
#include <string_view>

// Plain CDR (XCDR1), little-endian, as ROS 2 (rmw / Fast DDS) puts it on the wire and in bags:
// a 4-byte encapsulation header 00 01 00 00, then the fields. Each primitive of size n (1, 2, 4,
// 8) is aligned to n, counted from the end of the encapsulation header. Strings are a uint32
// length that includes the NUL, the bytes, and the NUL. Sequences are a uint32 element count
// and the elements; fixed arrays are the elements only.
namespace deepnav::cdr {

inline constexpr uint8_t kEncapsulationLe[4] = {0x00, 0x01, 0x00, 0x00};
inline constexpr size_t kEncapsulationSize = sizeof(kEncapsulationLe);

// Serialises into a caller-provided buffer; never allocates. Writing past the capacity sets
// ok() to false and stops writing, but size() keeps counting, so the same code measures the
// size a message needs: CdrWriter::sizer() counts without writing at all.
class CdrWriter {
 public:
  // Writes the encapsulation header at out[0].
  CdrWriter(uint8_t* out, size_t capacity);
  static CdrWriter sizer() { return CdrWriter(nullptr, 0); }

  void boolean(bool v) { u8(v ? 1 : 0); }
  void u8(uint8_t v) { primitive(&v, 1); }
  void i8(int8_t v) { primitive(&v, 1); }
  void u16(uint16_t v) { primitive(&v, 2); }
  void i16(int16_t v) { primitive(&v, 2); }
  void u32(uint32_t v) { primitive(&v, 4); }
  void i32(int32_t v) { primitive(&v, 4); }
  void u64(uint64_t v) { primitive(&v, 8); }
  void i64(int64_t v) { primitive(&v, 8); }
  void f32(float v) { primitive(&v, 4); }
  void f64(double v) { primitive(&v, 8); }
  void string(std::string_view s);
  // Element count of a sequence (T[]); the caller then writes the elements.
  void sequenceLength(size_t count) { u32(uint32_t(count)); }
  // Fixed arrays (T[N]): elements only.
  void u8Array(const uint8_t* data, size_t count);
  void f64Array(const double* data, size_t count);
  // Elements of 2 and 4 bytes (little-endian host), aligned once: the same bytes as u16() / f32() per
  // element, for image rows.
  void u16Array(const uint16_t* data, size_t count);
  void f32Array(const float* data, size_t count);
  // uint8[] sequence: count, then the bytes.
  void u8Sequence(const uint8_t* data, size_t count);

  bool ok() const { return ok_; }
  // Bytes written (or needed, after an overflow or when sizing), header included.
  size_t size() const { return pos_; }

 private:
  void align(size_t n);
  void raw(const void* data, size_t n);
  void primitive(const void* v, size_t n) {
    align(n);
    raw(v, n);
  }

  uint8_t* out_;
  size_t capacity_;
  size_t pos_ = 0;
  bool ok_ = true;
};

}  // namespace deepnav::cdr
