#include "drivers/cdr/cdr_writer.h"

#include <bit>
#include <cstring>

namespace deepnav::cdr {

static_assert(std::endian::native == std::endian::little,
              "CdrWriter copies primitives as they are in memory: little-endian hosts only");

CdrWriter::CdrWriter(uint8_t* out, size_t capacity) : out_(out), capacity_(capacity) {
  raw(kEncapsulationLe, kEncapsulationSize);
}

void CdrWriter::align(size_t n) {
  static constexpr uint8_t kZeros[8] = {};
  const size_t misalignment = (pos_ - kEncapsulationSize) % n;
  if (misalignment != 0) raw(kZeros, n - misalignment);
}

void CdrWriter::raw(const void* data, size_t n) {
  if (out_ != nullptr && ok_) {
    if (n <= capacity_ - pos_) {
      if (n > 0) std::memcpy(out_ + pos_, data, n);
    } else {
      ok_ = false;  // from here on only count
    }
  }
  pos_ += n;
}

void CdrWriter::string(std::string_view s) {
  u32(uint32_t(s.size() + 1));
  raw(s.data(), s.size());
  static constexpr uint8_t kNul = 0;
  raw(&kNul, 1);
}

void CdrWriter::u8Array(const uint8_t* data, size_t count) { raw(data, count); }

void CdrWriter::f64Array(const double* data, size_t count) {
  if (count == 0) return;
  align(8);
  raw(data, count * sizeof(double));
}

void CdrWriter::u16Array(const uint16_t* data, size_t count) {
  if (count == 0) return;
  align(2);
  raw(data, count * sizeof(uint16_t));
}

void CdrWriter::f32Array(const float* data, size_t count) {
  if (count == 0) return;
  align(4);
  raw(data, count * sizeof(float));
}

void CdrWriter::u8Sequence(const uint8_t* data, size_t count) {
  sequenceLength(count);
  raw(data, count);
}

}  // namespace deepnav::cdr
