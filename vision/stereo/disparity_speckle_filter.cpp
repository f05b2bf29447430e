#include "vision/stereo/disparity_speckle_filter.h"

#include <algorithm>
#include <cmath>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {
namespace {

// Two valid neighbours belong to one segment when their disparities differ by at most sim_px.
bool joins(float a, float b, float sim_px) {
  return (a >= 0.0f) & (b >= 0.0f) & (std::fabs(a - b) <= sim_px);
}

}  // namespace

bool DisparitySpeckleFilter::allocate(int width_px, int height_px) {
  if (width_px < 1 || height_px < 1) return false;
  width_px_ = width_px;
  height_px_ = height_px;
  const std::size_t pixels = static_cast<std::size_t>(width_px) * height_px;
  label_.assign(pixels, 0);
  // at most one run per pixel, and label 0 for the invalid pixels
  parent_.assign(pixels + 1, 0);
  size_.assign(pixels + 1, 0);
  remove_.assign(pixels + 1, 0);
  return true;
}

// Without a branch on the pixel values (they decide at random inside noisy areas), in integer masks: a
// run goes on while a pixel joins its left neighbour, and the newest label is the current run's. Every
// pixel writes its run's length so far and its label as its own parent; the last write of a run stays.
std::int32_t DisparitySpeckleFilter::labelRow(const float* d, int v, float sim_px,
                                              std::int32_t next_label) {
  const int width = width_px_;
  std::int32_t* label = label_.data() + static_cast<std::size_t>(v) * width;
  std::int32_t* parent = parent_.data();
  std::int32_t* size = size_.data();
  std::int32_t run = next_label - 1;  // the current run's label
  std::int32_t length = 0;
  float left = kInvalidDisparity;
  for (int u = 0; u < width; ++u) {
    const float x = d[u];
    // not below 0: a NaN is a pixel of its own (never joined), so a segment of one, as the flood fill had it
    const std::int32_t valid = !(x < 0.0f);
    const std::int32_t goes_on = joins(x, left, sim_px);  // implies valid
    run += valid & (goes_on ^ 1);
    length = (length & -goes_on) + valid;
    const std::int32_t own = run & -valid;
    label[u] = own;
    parent[own] = own;
    size[own] = length;
    left = x;
  }
  return run + 1;
}

// One union per pair of overlapping runs: along a run joined to one run above, the pair repeats.
void DisparitySpeckleFilter::linkRows(const float* d, int v, float sim_px) {
  const int width = width_px_;
  const float* up = d - width;
  const std::int32_t* label = label_.data() + static_cast<std::size_t>(v) * width;
  const std::int32_t* label_up = label - width;
  std::int32_t last_a = 0, last_b = 0;  // the pair linked last
  for (int u = 0; u < width; ++u) {
    const std::int32_t a = label[u], b = label_up[u];
    if (joins(d[u], up[u], sim_px) & ((a != last_a) | (b != last_b))) {
      last_a = a;
      last_b = b;
      unite(a, b);
    }
  }
}

std::int32_t DisparitySpeckleFilter::find(std::int32_t x) {
  while (parent_[x] != x) {
    parent_[x] = parent_[parent_[x]];  // path halving
    x = parent_[x];
  }
  return x;
}

// The smaller label becomes the root, so that every parent is smaller than its child (flattened in
// one forward pass by apply()).
void DisparitySpeckleFilter::unite(std::int32_t a, std::int32_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return;
  if (a > b) std::swap(a, b);
  parent_[b] = a;
  size_[a] += size_[b];
}

void DisparitySpeckleFilter::apply(int min_size_px, float sim_px, cv::Mat* disparity_px) {
  float* d = disparity_px->ptr<float>(0);  // continuous: allocated by the caller as one block
  std::int32_t next_label = 1;
  for (int v = 0; v < height_px_; ++v) {
    const float* row = d + static_cast<std::size_t>(v) * width_px_;
    next_label = labelRow(row, v, sim_px, next_label);
    if (v > 0) linkRows(row, v, sim_px);
  }
  // every parent is smaller than its label: in increasing order, each label's parent already points
  // at its root
  remove_[0] = 0;
  for (std::int32_t l = 1; l < next_label; ++l) {
    parent_[l] = parent_[parent_[l]];
    remove_[l] = size_[parent_[l]] < min_size_px ? 1 : 0;
  }
  const std::size_t pixels = static_cast<std::size_t>(width_px_) * height_px_;
  for (std::size_t i = 0; i < pixels; ++i) {
    d[i] = remove_[label_[i]] ? kInvalidDisparity : d[i];
  }
}

}  // namespace deepnav
