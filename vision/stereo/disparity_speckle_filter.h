#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// Removes small segments (speckles): 4-connected regions of valid disparities whose neighbours
// differ by at most sim_px and which cover fewer than min_size_px pixels are set invalid (-1).
// Such islands are almost always mismatches in texture-poor or occluded areas (Geiger et al.
// 2010, post-processing). Buffers are allocated once.
//
// The segments are found row by row, as runs joined by union-find (two-pass connected-component
// labelling): each row's runs of joined neighbours get a label, a label is linked to the labels of
// the row above wherever a pixel joins the one above it, and each set's size is the sum of its runs.
// That is the flood fill's partition (joining is symmetric) with a few stores per pixel and one union
// per pair of overlapping runs, instead of a stack push and four neighbour visits per pixel.
class DisparitySpeckleFilter {
 public:
  bool allocate(int width_px, int height_px);
  void apply(int min_size_px, float sim_px, cv::Mat* disparity_px);

 private:
  // Labels the runs of row v (labels continue from next_label, 0 for invalid pixels); returns the
  // next free label.
  std::int32_t labelRow(const float* d, int v, float sim_px, std::int32_t next_label);
  // Links the runs of row v to those of row v - 1 wherever a pixel joins the one above.
  void linkRows(const float* d, int v, float sim_px);
  std::int32_t find(std::int32_t label);
  void unite(std::int32_t a, std::int32_t b);

  int width_px_ = 0;
  int height_px_ = 0;
  std::vector<std::int32_t> label_;   // per pixel: its run's label, 0 when invalid
  std::vector<std::int32_t> parent_;  // per label: a smaller label of its set, or itself at the root
  std::vector<std::int32_t> size_;    // per label: its run's length; at a root, the set's size
  std::vector<std::uint8_t> remove_;  // per label: its set is smaller than the minimum
};

}  // namespace deepnav
