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
  stack_.assign(2 * pixels, 0);
  members_.assign(pixels, 0);
  return true;
}

// Flood fill from seed; the segment's pixel indices end up in members_[0 .. size).
int DisparitySpeckleFilter::floodSegment(const cv::Mat& disparity_px, int seed, float sim_px,
                                         std::int32_t label) {
  const float* d = disparity_px.ptr<float>(0);
  const int last_row_start = (height_px_ - 1) * width_px_;
  int top = 0;
  int size = 0;
  const auto push = [&](int i, int u) {
    stack_[top++] = i;
    stack_[top++] = u;
  };
  push(seed, seed % width_px_);
  label_[seed] = label;
  while (top > 0) {
    const int u = stack_[--top];
    const int i = stack_[--top];
    members_[size++] = i;
    const float d_i = d[i];
    // left, right, up, down, the order of a plain neighbour list. Without a branch on the pixel
    // values (they decide at random inside noisy areas): the neighbour is always written above the
    // top of the stack, and the top only moves over it when it joins the segment.
    const auto visit = [&](int n, int un) {
      const bool joins = (label_[n] == 0) & (d[n] >= 0.0f) & (std::fabs(d[n] - d_i) <= sim_px);
      label_[n] = joins ? label : label_[n];
      stack_[top] = n;
      stack_[top + 1] = un;
      top += joins ? 2 : 0;
    };
    if (u > 0) visit(i - 1, u - 1);
    if (u + 1 < width_px_) visit(i + 1, u + 1);
    if (i >= width_px_) visit(i - width_px_, u);
    if (i < last_row_start) visit(i + width_px_, u);
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
