#include "vision/stereo/disparity_speckle_filter.h"

#include <cmath>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {

bool DisparitySpeckleFilter::allocate(int width_px, int height_px) {
  if (width_px < 1 || height_px < 1) return false;
  width_px_ = width_px;
  height_px_ = height_px;
  const std::size_t pixels = static_cast<std::size_t>(width_px) * height_px;
  label_.assign(pixels, 0);
  stack_.assign(pixels, 0);
  members_.assign(pixels, 0);
  return true;
}

// Flood fill from seed; the segment's pixel indices end up in members_[0 .. size).
int DisparitySpeckleFilter::floodSegment(const cv::Mat& disparity_px, int seed, float sim_px,
                                         std::int32_t label) {
  const float* d = disparity_px.ptr<float>(0);
  int top = 0;
  int size = 0;
  stack_[top++] = seed;
  label_[seed] = label;
  while (top > 0) {
    const int i = stack_[--top];
    members_[size++] = i;
    const int u = i % width_px_;
    const int v = i / width_px_;
    const int neighbours[4] = {u > 0 ? i - 1 : -1, u + 1 < width_px_ ? i + 1 : -1,
                               v > 0 ? i - width_px_ : -1, v + 1 < height_px_ ? i + width_px_ : -1};
    for (int n : neighbours) {
      if (n < 0 || label_[n] != 0 || d[n] < 0.0f || std::fabs(d[n] - d[i]) > sim_px) continue;
      label_[n] = label;
      stack_[top++] = n;
    }
  }
  return size;
}

void DisparitySpeckleFilter::apply(int min_size_px, float sim_px, cv::Mat* disparity_px) {
  std::fill(label_.begin(), label_.end(), 0);
  float* d = disparity_px->ptr<float>(0);  // continuous: allocated by the caller as one block
  const int pixels = width_px_ * height_px_;
  std::int32_t label = 0;
  for (int i = 0; i < pixels; ++i) {
    if (label_[i] != 0 || d[i] < 0.0f) continue;
    const int size = floodSegment(*disparity_px, i, sim_px, ++label);
    if (size >= min_size_px) continue;
    for (int k = 0; k < size; ++k) d[members_[k]] = kInvalidDisparity;
  }
}

}  // namespace deepnav
