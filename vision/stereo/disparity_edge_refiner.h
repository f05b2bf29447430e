#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// Edge-aware clean-up of a disparity map at its discontinuities. Window matching "fattens" the
// nearer surface by about half a window across a depth edge, and the left-right check cannot see
// it because both views fatten alike. Depth edges mostly coincide with image edges, so every
// valid pixel within radius_px of a disparity jump (> jump_px between 4-neighbours) takes the
// weighted median of the valid disparities in its (2 radius + 1)^2 window (sampled every second
// pixel in both directions, the centre included), each neighbour q
// weighted by its colour similarity to the pixel p, w = exp(-|I_p - I_q|_1 / sigma) (sum over BGR,
// or 3x the grey difference): a joint weighted median as in Ma et al., "Constant Time Weighted
// Median Filtering for Stereo Matching and Beyond", ICCV 2013. Filtering only the band around
// jumps keeps the cost a fraction of a full-image filter. Buffers are allocated once.
class DisparityEdgeRefiner {
 public:
  bool allocate(int width_px, int height_px, int num_disparities);
  // guide: CV_8UC1 or CV_8UC3 of the allocated size; disparity_px: CV_32F of that size. Invalid
  // pixels (d < 0) neither vote nor change.
  void apply(const cv::Mat& guide, int radius_px, float jump_px, float sigma,
             cv::Mat* disparity_px);

 private:
  void markJumps(const cv::Mat& disparity_px, float jump_px);
  void dilateJumps(int radius_px);
  float weightedMedian(const cv::Mat& guide, int u, int v, int radius_px);

  int width_px_ = 0;
  int height_px_ = 0;
  int bins_ = 0;
  std::vector<std::uint8_t> jump_;  // 1 where a 4-neighbour differs by more than the jump
  std::vector<std::uint8_t> band_;  // jump_ dilated by the radius (rows, then columns)
  std::vector<std::uint8_t> rows_;  // scratch of the separable dilation
  std::vector<float> weight_lut_;   // exp(-diff / sigma), diff = 0 .. 765
  std::vector<float> hist_w_;       // per integer disparity: sum of weights
  std::vector<float> hist_wd_;      // per integer disparity: sum of weight * d
  cv::Mat source_px_;               // the input map, read while the output is written
  float lut_sigma_ = -1.0f;
};

}  // namespace deepnav
