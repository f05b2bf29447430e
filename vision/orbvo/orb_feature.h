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

inline int hammingDistance(const OrbDescriptor& a, const OrbDescriptor& b) {
  return std::popcount(a[0] ^ b[0]) + std::popcount(a[1] ^ b[1]) + std::popcount(a[2] ^ b[2]) +
         std::popcount(a[3] ^ b[3]);
}

}  // namespace deepnav
