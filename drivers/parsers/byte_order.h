#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>

// Fixed-width reads from a byte range whose size the caller has already checked. Every parser checks
// `offset + width <= size` before calling these; they never look at anything else.
namespace deepnav {

inline uint16_t readLe16(const uint8_t* p) { return uint16_t(p[0] | (p[1] << 8)); }
inline int16_t readLeI16(const uint8_t* p) { return int16_t(readLe16(p)); }
inline uint32_t readLe32(const uint8_t* p) {
  return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}
inline int32_t readLeI32(const uint8_t* p) { return int32_t(readLe32(p)); }
inline uint16_t readBe16(const uint8_t* p) { return uint16_t((p[0] << 8) | p[1]); }
inline uint32_t readBe32(const uint8_t* p) {
  return (uint32_t(p[0]) << 24) | (uint32_t(p[1]) << 16) | (uint32_t(p[2]) << 8) | uint32_t(p[3]);
}
inline uint64_t readBe64(const uint8_t* p) { return (uint64_t(readBe32(p)) << 32) | readBe32(p + 4); }
inline float readBeF32(const uint8_t* p) {
  const uint32_t bits = readBe32(p);
  float v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}
inline double readBeF64(const uint8_t* p) {
  const uint64_t bits = readBe64(p);
  double v;
  std::memcpy(&v, &bits, sizeof v);
  return v;
}

}  // namespace deepnav
