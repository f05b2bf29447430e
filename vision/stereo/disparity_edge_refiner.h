#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// Parameters of DisparityEdgeRefiner.
struct EdgeRefineParams {
  int band_px = 4;       // pixels this close to a jump are re-estimated (0 disables the refiner)
  int radius_px = 8;     // window radius of the weighted median
  float jump_px = 2.0f;  // a jump: 4-neighbours differ by more than this
  float sigma = 10.0f;   // colour distance scale (sum of |dB|+|dG|+|dR|, or 3 |dGrey|)
  float budget = 24.0f;  // mean window samples per image pixel allowed (bounds the cost)
};

// Edge-aware clean-up of a disparity map at its discontinuities. Window matching "fattens" the
// nearer surface by about half a window across a depth edge, and the left-right check cannot see
// it because both views fatten alike. Depth edges mostly coincide with image edges, so every
// valid pixel within band_px of a disparity jump takes the weighted median of the valid
// disparities in its (2 radius + 1)^2 window, each neighbour q weighted by its colour similarity
// to the pixel p, w = exp(-|I_p - I_q|_1 / sigma): a joint weighted median as in Ma et al.,
// "Constant Time Weighted Median Filtering for Stereo Matching and Beyond", ICCV 2013.
// The window is sampled on a lattice centred on p, every 2 px; when the band is so large (noisy
// maps of low-contrast frames) that this would exceed budget samples per image pixel, every 4 or
// 8 px: the cost stays bounded. Buffers are allocated once.
class DisparityEdgeRefiner {
 public:
  bool allocate(int width_px, int height_px, int num_disparities);
  // guide: CV_8UC1 or CV_8UC3 of the allocated size; disparity_px: CV_32F of that size. Invalid
  // pixels (d < 0) neither vote nor change.
  void apply(const cv::Mat& guide, const EdgeRefineParams& params, cv::Mat* disparity_px);

 private:
  void markJumps(const cv::Mat& disparity_px, float jump_px);
  template <int kChannels>
  void markGuideKeys(const cv::Mat& guide);
  void dilateJumps(int radius_px);
  void dilateColumns(const std::uint8_t* in, std::uint8_t* out, int radius_px);
  template <int kChannels>
  void refineBand(const cv::Mat& guide, int radius_px, cv::Mat* disparity_px);
  template <int kChannels>
  float weightedMedian(const cv::Mat& guide, int u, int v, int reach);

  int width_px_ = 0;
  int height_px_ = 0;
  int bins_ = 0;
  int stride_px_ = 2;
  std::vector<std::uint8_t> jump_;  // 1 where a 4-neighbour differs by more than the jump
  std::vector<std::uint8_t> band_;  // jump_ dilated by band_px (rows, then columns)
  std::vector<std::uint8_t> rows_;  // scratch of the separable dilation
  std::vector<std::int32_t> column_count_;  // per column: flags within the dilation window
  std::vector<std::uint16_t> bin_;  // integer disparity of each pixel, the spare bin bins_ when invalid
  std::vector<std::uint16_t> guide_key_;  // grey level (grey guide) or 0 (colour), past the weights when invalid
  std::vector<float> weight_lut_;   // exp(-diff / sigma), diff = 0 .. 765, then zeros
  std::vector<float> weight_by_grey_diff_;  // weight_lut_[3 |g|], g = grey difference -255 .. 255, at g + 255; then zeros
  std::vector<float> hist_w_;       // per integer disparity and the spare bin: sum of weights (zero between windows)
  std::vector<float> hist_wd_;      // per integer disparity: sum of weight * d
  cv::Mat source_px_;               // the input map, read while the output is written
  float lut_sigma_ = -1.0f;
};

}  // namespace deepnav
