#pragma once
#include <cstddef>
#include <cstdint>

namespace deepnav::mcap {

// CRC-32 as used by MCAP (and zlib, PNG, Ethernet): reflected polynomial 0xEDB88320,
// initial value and final xor 0xFFFFFFFF. Incremental: pass the previous result as `crc` to
// continue a checksum over several buffers; start with 0.
uint32_t crc32Update(uint32_t crc, const uint8_t* data, size_t size);

inline uint32_t crc32(const uint8_t* data, size_t size) { return crc32Update(0, data, size); }

}  // namespace deepnav::mcap
