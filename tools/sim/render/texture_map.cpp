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
  texels_.clear();
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
    const cv::Vec3b* row = bgr.ptr<cv::Vec3b>(source(y, rows));
    for (int x = -1; x <= cols; ++x) {
      const cv::Vec3b& t = row[source(x, cols)];
      const std::uint8_t bytes[4] = {t[0], t[1], t[2], 0};
      std::memcpy(&texels_[offset + static_cast<std::size_t>(y + 1) * stride + (x + 1)], bytes, sizeof(bytes));
    }
  }
}

}  // namespace deepnav::sim
