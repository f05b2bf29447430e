#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "tools/sim/render/float4.h"

namespace deepnav::sim {

// An albedo image (BGR, linear, 8 bits per channel: value / 255 is the albedo) with its mip pyramid,
// sampled bilinearly from the level that matches the pixel footprint (no shimmering when the panel is
// far, crisp edges when it is near). Texel i covers [i, i + 1) in texel coordinates.
class TextureMap {
 public:
  // wrap: the texture tiles (width and height must be powers of two); else coordinates are clamped.
  bool create(int width_texels, int height_texels, bool wrap);
  // Level 0, CV_8UC3, to paint into before buildMips().
  cv::Mat& base() { return levels_[0]; }
  const cv::Mat& base() const { return levels_[0]; }
  // Box-filtered levels down to about 8 texels.
  void buildMips();

  // Albedo at level-0 texel coordinates (u, v) for a pixel covering a square of footprint2_texels
  // (level-0 texels, squared side): level floor(log2(side)), clamped. B, G, R in lanes 0-2, lane 3 is 0
  // (the shading works on 4-float vectors).
  Eigen::Vector4f sample(float u, float v, float footprint2_texels) const {
    return sampleLevel(levelFor(footprint2_texels), u, v);
  }
  // floor(log2(side)) = floor(e / 2) for footprint2 = m 2^e, m in [1, 2), read from the float's
  // exponent bits instead of a loop of divisions by 4 (the same level: both are exact).
  int levelFor(float footprint2_texels) const {
    if (!(footprint2_texels >= 4.0f)) return 0;
    const int exponent = static_cast<int>((std::bit_cast<std::uint32_t>(footprint2_texels) >> 23) & 0xFFu) - 127;
    return std::min(exponent / 2, static_cast<int>(levels_.size()) - 1);
  }
  inline Eigen::Vector4f sampleLevel(int level, float u, float v) const;
  int levels() const { return static_cast<int>(levels_.size()); }

 private:

  struct Level {  // raw view of one level for the sampler
    const std::uint8_t* data;
    std::size_t step;
    int cols, rows;
    float scale;
  };
  std::vector<cv::Mat> levels_;
  std::vector<Level> view_;
  std::vector<float> scale_;  // level-L texels per level-0 texel (both axes; sizes halve exactly or clamp)
  bool wrap_ = false;
};

inline constexpr std::array<float, 256> kByteToFloat = [] {
  std::array<float, 256> table{};
  for (int i = 0; i < 256; ++i) table[i] = static_cast<float>(i);
  return table;
}();

inline Eigen::Vector4f TextureMap::sampleLevel(int level, float u, float v) const {
  const Level& L = view_[level];
  const float x = u * L.scale - 0.5f, y = v * L.scale - 0.5f;
  // floor without a libm call (no SSE4.1 rounding in the x86-64 baseline): truncate, then fix negatives.
  int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  x0 -= x < static_cast<float>(x0);
  y0 -= y < static_cast<float>(y0);
  const float ax = x - static_cast<float>(x0), ay = y - static_cast<float>(y0);
  int x1 = x0 + 1, y1 = y0 + 1;
  if (wrap_) {
    x0 &= L.cols - 1, x1 &= L.cols - 1, y0 &= L.rows - 1, y1 &= L.rows - 1;
  } else {
    x0 = std::clamp(x0, 0, L.cols - 1), x1 = std::clamp(x1, 0, L.cols - 1);
    y0 = std::clamp(y0, 0, L.rows - 1), y1 = std::clamp(y1, 0, L.rows - 1);
  }
  const std::uint8_t* r0 = L.data + static_cast<std::ptrdiff_t>(y0) * L.step;
  const std::uint8_t* r1 = L.data + static_cast<std::ptrdiff_t>(y1) * L.step;
  const float w00 = (1.0f - ax) * (1.0f - ay), w10 = ax * (1.0f - ay);
  const float w01 = (1.0f - ax) * ay, w11 = ax * ay;
  const std::uint8_t *a = r0 + 3 * x0, *b = r0 + 3 * x1, *c = r1 + 3 * x0, *d = r1 + 3 * x1;
  constexpr float k = 1.0f / 255.0f;
  const float* f = kByteToFloat.data();  // float(byte) by a load: cvtsi2ss stalls on its register
  // Built in a register: Eigen's constructor from four scalars went through the stack (4- and 8-byte
  // stores read back by one 16-byte load, which cannot be store-forwarded: a stall per fetch).
  const Float4 bgr = {w00 * f[a[0]] + w10 * f[b[0]] + w01 * f[c[0]] + w11 * f[d[0]],
                      w00 * f[a[1]] + w10 * f[b[1]] + w01 * f[c[1]] + w11 * f[d[1]],
                      w00 * f[a[2]] + w10 * f[b[2]] + w01 * f[c[2]] + w11 * f[d[2]], 0.0f};
  return toVector4f(bgr * k);
}

}  // namespace deepnav::sim
