#include "tools/sim/render/texture_map.h"

#include <algorithm>
#include <cmath>

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
  view_.clear();
  for (std::size_t k = 0; k < levels_.size(); ++k)
    view_.push_back({levels_[k].ptr<std::uint8_t>(), levels_[k].step[0], levels_[k].cols, levels_[k].rows, scale_[k]});
}

}  // namespace deepnav::sim
