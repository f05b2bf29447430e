#include "tools/sim/render/texture_map.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <opencv2/imgproc.hpp>

namespace deepnav::sim {

namespace {
bool isPowerOfTwo(int n) { return n > 0 && (n & (n - 1)) == 0; }
}  // namespace

bool TextureMap::create(int width_texels, int height_texels, bool wrap) {
  if (width_texels < 2 || height_texels < 2) return false;
  if (wrap && (!isPowerOfTwo(width_texels) || !isPowerOfTwo(height_texels))) return false;
  wrap_ = wrap;
  levels_.assign(1, cv::Mat(height_texels, width_texels, CV_8UC3, cv::Scalar::all(0)));
  scale_.assign(1, 1.0f);
  buildMips();
  return true;
}

void TextureMap::buildMips() {
  levels_.resize(1);
  scale_.assign(1, 1.0f);
  while (levels_.back().cols >= 16 && levels_.back().rows >= 16) {
    const cv::Mat& prev = levels_.back();
    cv::Mat next;
    cv::resize(prev, next, cv::Size(prev.cols / 2, prev.rows / 2), 0.0, 0.0, cv::INTER_AREA);
    scale_.push_back(static_cast<float>(next.cols) / static_cast<float>(levels_[0].cols));
    levels_.push_back(next);
  }
  std::size_t words = 0;
  for (const cv::Mat& level : levels_) words += static_cast<std::size_t>(level.cols + 2) * (level.rows + 2);
  texels_.clear();
  texels_.reserve(words);
  view_.clear();
  for (const cv::Mat& level : levels_) packLevel(level);
}

void TextureMap::packLevel(const cv::Mat& bgr) {
  const int cols = bgr.cols, rows = bgr.rows, stride = cols + 2;
  const std::size_t offset = texels_.size();
  view_.push_back({static_cast<std::ptrdiff_t>(offset), stride, cols, rows, scale_[view_.size()]});
  texels_.resize(offset + static_cast<std::size_t>(stride) * (rows + 2));
  // The texel a border position repeats: the opposite edge when wrapping, the edge itself when clamping.
  const auto source = [&](int i, int n) { return i < 0 ? (wrap_ ? n - 1 : 0) : i >= n ? (wrap_ ? 0 : n - 1) : i; };
  for (int y = -1; y <= rows; ++y) {
    const std::uint8_t* row = bgr.ptr<std::uint8_t>(source(y, rows));
    std::uint32_t* out = &texels_[offset + static_cast<std::size_t>(y + 1) * stride];
    for (int x = 0; x < cols; ++x) {
      const std::uint8_t bytes[4] = {row[3 * x], row[3 * x + 1], row[3 * x + 2], 0};
      std::memcpy(&out[x + 1], bytes, sizeof(bytes));
    }
    out[0] = out[source(-1, cols) + 1];
    out[cols + 1] = out[source(cols, cols) + 1];
  }
}

void TextureMap::sample4(Float4 u, Float4 v, Float4 footprint2_texels, Eigen::Vector4f out[4]) const {
  // levelFor(), lane-wise: floor(log2(side)) from the float's exponent bits, 0 below 4 texels^2.
  const Int4 exponent = ((reinterpret_cast<Int4>(footprint2_texels) >> 23) & 0xFF) - 127;
  const int top = static_cast<int>(levels_.size()) - 1;
  const Int4 half = exponent / 2;
  const Int4 level = footprint2_texels >= 4.0f ? (top < half ? Int4{} + top : half) : Int4{};
  if (level[0] != level[1] || level[0] != level[2] || level[0] != level[3]) {
    for (int i = 0; i < 4; ++i) out[i] = sample(u[i], v[i], footprint2_texels[i]);
    return;
  }
  // sampleLevel(), lane-wise up to the texel loads (its comments give the why).
  const Level& L = view_[level[0]];
  const Float4 x = u * L.scale - 0.5f, y = v * L.scale - 0.5f;
  Int4 x0 = __builtin_convertvector(x, Int4), y0 = __builtin_convertvector(y, Int4);
  x0 += x < __builtin_convertvector(x0, Float4);  // a true comparison is -1 in a lane: floor
  y0 += y < __builtin_convertvector(y0, Float4);
  const Float4 ax = x - __builtin_convertvector(x0, Float4), ay = y - __builtin_convertvector(y0, Float4);
  if (wrap_) {
    x0 &= L.cols - 1, y0 &= L.rows - 1;
  } else {  // std::clamp(x0, -1, cols - 1): x0 < lo ? lo : hi < x0 ? hi : x0
    x0 = x0 < -1 ? Int4{} - 1 : (L.cols - 1 < x0 ? Int4{} + (L.cols - 1) : x0);
    y0 = y0 < -1 ? Int4{} - 1 : (L.rows - 1 < y0 ? Int4{} + (L.rows - 1) : y0);
  }
  const Int4 first = static_cast<int>(L.offset) + (y0 + 1) * static_cast<int>(L.stride) + (x0 + 1);
  const Float4 w00 = (1.0f - ax) * (1.0f - ay), w10 = ax * (1.0f - ay);
  const Float4 w01 = (1.0f - ax) * ay, w11 = ax * ay;
  constexpr float k = 1.0f / 255.0f;
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t* r0 = texels_.data() + first[i];
    Float4 t00, t10, t01, t11;
    texelPairFloat4(r0, &t00, &t10);
    texelPairFloat4(r0 + L.stride, &t01, &t11);
    const Float4 bgr = w00[i] * t00 + w10[i] * t10 + w01[i] * t01 + w11[i] * t11;
    out[i] = toVector4f(bgr * k);
  }
}

}  // namespace deepnav::sim
