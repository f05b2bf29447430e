#pragma once
#include <array>
#include <bit>
#include <cstdint>

namespace deepnav {

// One oriented FAST corner. Coordinates are in level-0 pixels whatever the pyramid level it was
// found on.
struct OrbFeature {
  float u_px = 0.0f;
  float v_px = 0.0f;
  float angle_rad = 0.0f;  // intensity-centroid orientation, image axes (x right, y down)
  float response = 0.0f;   // FAST score
  int level = 0;           // pyramid level (scale = scale_factor^level)
};

// 256-bit steered-BRIEF descriptor.
using OrbDescriptor = std::array<std::uint64_t, 4>;

// Number of differing bits. Without a hardware popcount in the target flags (x86-64 baseline), GCC
// turns std::popcount into a libgcc call per word; the inline SWAR count (Warren, "Hacker's
// Delight", sec. 5-1) is several times faster there: the byte counts of the four words are summed
// (each byte stays <= 32), then added across the bytes.
inline int hammingDistance(const OrbDescriptor& a, const OrbDescriptor& b) {
#if defined(__POPCNT__) || defined(__aarch64__)
  return std::popcount(a[0] ^ b[0]) + std::popcount(a[1] ^ b[1]) + std::popcount(a[2] ^ b[2]) +
         std::popcount(a[3] ^ b[3]);
#else
  std::uint64_t bytes = 0;
  for (int i = 0; i < 4; ++i) {
    std::uint64_t x = a[i] ^ b[i];
    x = x - ((x >> 1) & 0x5555555555555555ull);
    x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
    bytes += (x + (x >> 4)) & 0x0F0F0F0F0F0F0F0Full;
  }
  // Pairs of bytes into 16-bit lanes (<= 64 each), then the lanes into the top 16 bits (<= 256).
  const std::uint64_t lanes =
      (bytes & 0x00FF00FF00FF00FFull) + ((bytes >> 8) & 0x00FF00FF00FF00FFull);
  return static_cast<int>((lanes * 0x0001000100010001ull) >> 48);
#endif
}

}  // namespace deepnav
