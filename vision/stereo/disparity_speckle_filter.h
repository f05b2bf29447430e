#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// Removes small segments (speckles): 4-connected regions of valid disparities whose neighbours
// differ by at most sim_px and which cover fewer than min_size_px pixels are set invalid (-1).
// Such islands are almost always mismatches in texture-poor or occluded areas (Geiger et al.
// 2010, post-processing). Label and stack buffers are allocated once.
class DisparitySpeckleFilter {
 public:
  bool allocate(int width_px, int height_px);
  void apply(int min_size_px, float sim_px, cv::Mat* disparity_px);

 private:
  int floodSegment(const cv::Mat& disparity_px, int seed, float sim_px, std::int32_t label);

  int width_px_ = 0;
  int height_px_ = 0;
  std::vector<std::int32_t> label_;
  std::vector<std::int32_t> stack_;  // pixel index and column of each pixel to visit (no division)
  std::vector<std::int32_t> members_;
};

}  // namespace deepnav
