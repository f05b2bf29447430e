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
}

Eigen::Vector3f TextureMap::sample(float u, float v, float footprint_texels) const {
  int level = 0;
  const int last = static_cast<int>(levels_.size()) - 1;
  while (footprint_texels >= 2.0f && level < last) {
    footprint_texels *= 0.5f;
    ++level;
  }
  return sampleLevel(level, u, v);
}

Eigen::Vector3f TextureMap::sampleLevel(int level, float u, float v) const {
  const cv::Mat& img = levels_[level];
  const float s = scale_[level];
  const float x = u * s - 0.5f, y = v * s - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float ax = x - fx, ay = y - fy;
  int x0 = static_cast<int>(fx), y0 = static_cast<int>(fy), x1 = x0 + 1, y1 = y0 + 1;
  if (wrap_) {
    const int mx = img.cols - 1, my = img.rows - 1;
    x0 &= mx, x1 &= mx, y0 &= my, y1 &= my;
  } else {
    x0 = std::clamp(x0, 0, img.cols - 1), x1 = std::clamp(x1, 0, img.cols - 1);
    y0 = std::clamp(y0, 0, img.rows - 1), y1 = std::clamp(y1, 0, img.rows - 1);
  }
  const std::uint8_t* r0 = img.ptr<std::uint8_t>(y0);
  const std::uint8_t* r1 = img.ptr<std::uint8_t>(y1);
  const float w00 = (1.0f - ax) * (1.0f - ay), w10 = ax * (1.0f - ay);
  const float w01 = (1.0f - ax) * ay, w11 = ax * ay;
  Eigen::Vector3f out;
  for (int c = 0; c < 3; ++c) {
    out[c] = w00 * r0[3 * x0 + c] + w10 * r0[3 * x1 + c] + w01 * r1[3 * x0 + c] + w11 * r1[3 * x1 + c];
  }
  return out * (1.0f / 255.0f);
}

}  // namespace deepnav::sim
