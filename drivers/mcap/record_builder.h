#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "drivers/mcap/format.h"

// Little-endian serialisation of MCAP fields into a byte vector. The writer reserves its vectors
// at open(), so these appends stay within capacity and do not allocate in steady state.
namespace deepnav::mcap {

inline void putU8(std::vector<uint8_t>& out, uint8_t v) { out.push_back(v); }

inline void putLe(std::vector<uint8_t>& out, uint64_t v, size_t bytes) {
  for (size_t i = 0; i < bytes; ++i) out.push_back(uint8_t(v >> (8 * i)));
}

inline void putU16(std::vector<uint8_t>& out, uint16_t v) { putLe(out, v, 2); }
inline void putU32(std::vector<uint8_t>& out, uint32_t v) { putLe(out, v, 4); }
inline void putU64(std::vector<uint8_t>& out, uint64_t v) { putLe(out, v, 8); }

inline void putBytes(std::vector<uint8_t>& out, const uint8_t* data, size_t size) {
  if (size == 0) return;
  const size_t at = out.size();
  out.resize(at + size);
  std::memcpy(out.data() + at, data, size);
}

// MCAP String: uint32 byte length, then the bytes (no terminator).
inline void putString(std::vector<uint8_t>& out, std::string_view s) {
  putU32(out, uint32_t(s.size()));
  putBytes(out, reinterpret_cast<const uint8_t*>(s.data()), s.size());
}

// Overwrites 4 or 8 bytes at `at` (used to patch lengths once the content is known).
inline void patchLe(std::vector<uint8_t>& out, size_t at, uint64_t v, size_t bytes) {
  for (size_t i = 0; i < bytes; ++i) out[at + i] = uint8_t(v >> (8 * i));
}

// Starts a record: opcode and a placeholder length. Returns the position of the length field
// for endRecord().
inline size_t beginRecord(std::vector<uint8_t>& out, Opcode op) {
  putU8(out, uint8_t(op));
  const size_t length_at = out.size();
  putU64(out, 0);
  return length_at;
}

inline void endRecord(std::vector<uint8_t>& out, size_t length_at) {
  patchLe(out, length_at, out.size() - length_at - 8, 8);
}

// Map/Array fields carry a uint32 byte length in front of their entries.
inline size_t beginU32Block(std::vector<uint8_t>& out) {
  const size_t at = out.size();
  putU32(out, 0);
  return at;
}

inline void endU32Block(std::vector<uint8_t>& out, size_t at) {
  patchLe(out, at, out.size() - at - 4, 4);
}

}  // namespace deepnav::mcap
