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
  // Four samples (lanes) at once, bit for bit as sample() per lane: when the four use one mip level
  // (neighbouring pixels nearly always do) the level, coordinates and weights are computed lane-wise and
  // only the texel loads and the weighted sums per lane; else sample() per lane.
  void sample4(Float4 u, Float4 v, Float4 footprint2_texels, Eigen::Vector4f out[4]) const;
  int levels() const { return static_cast<int>(levels_.size()); }

 private:

  // One level for the sampler: texels as 4 bytes (B, G, R, 0) in a grid with a one-texel border, so that
  // texel (x, y), x in [-1, cols], y in [-1, rows], is at texels_[offset + (y + 1) stride + x + 1]. The
  // border repeats the opposite edge (wrap) or the edge itself (clamp): the bilinear pair (x0, x0 + 1) is
  // then always two adjacent words (one 8-byte load per row) once x0 is wrapped into [0, cols) or clamped
  // into [-1, cols).
  struct Level {
    std::ptrdiff_t offset, stride;
    int cols, rows;
    float scale;
  };
  void packLevel(const cv::Mat& bgr);  // appends one level to texels_ and view_
  std::vector<cv::Mat> levels_;
  std::vector<std::uint32_t> texels_;  // all levels, as Level describes (offsets, not pointers: copyable)
  std::vector<Level> view_;
  std::vector<float> scale_;  // level-L texels per level-0 texel (both axes; sizes halve exactly or clamp)
  bool wrap_ = false;
};

inline Eigen::Vector4f TextureMap::sampleLevel(int level, float u, float v) const {
  const Level& L = view_[level];
  const float x = u * L.scale - 0.5f, y = v * L.scale - 0.5f;
  // floor without a libm call (no SSE4.1 rounding in the x86-64 baseline): truncate, then fix negatives.
  int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  x0 -= x < static_cast<float>(x0);
  y0 -= y < static_cast<float>(y0);
  const float ax = x - static_cast<float>(x0), ay = y - static_cast<float>(y0);
  // Wrapped into [0, cols) or clamped into [-1, cols): with the border, (x0, x0 + 1) and (y0, y0 + 1)
  // address the same texels as wrapping or clamping each of the four separately.
  if (wrap_) {
    x0 &= L.cols - 1, y0 &= L.rows - 1;
  } else {
    x0 = std::clamp(x0, -1, L.cols - 1), y0 = std::clamp(y0, -1, L.rows - 1);
  }
  const std::uint32_t* r0 = texels_.data() + L.offset + (y0 + 1) * L.stride + (x0 + 1);
  const float w00 = (1.0f - ax) * (1.0f - ay), w10 = ax * (1.0f - ay);
  const float w01 = (1.0f - ax) * ay, w11 = ax * ay;
  // Four texels to four lanes each (lane 3 is 0), two per row in one load. The sum in the same order as
  // per channel in scalars (bit-identical), on B, G, R at once.
  Float4 t00, t10, t01, t11;
  texelPairFloat4(r0, &t00, &t10);
  texelPairFloat4(r0 + L.stride, &t01, &t11);
  const Float4 bgr = w00 * t00 + w10 * t10 + w01 * t01 + w11 * t11;
  constexpr float k = 1.0f / 255.0f;
  return toVector4f(bgr * k);
}

}  // namespace deepnav::sim
