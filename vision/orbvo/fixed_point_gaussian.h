#pragma once
#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// Gaussian smoothing of 8-bit images that reproduces cv::GaussianBlur(src, dst, Size(k, k), sigma) bit
// for bit (BORDER_REFLECT_101) in about half its instructions: the blur before BRIEF sampling was 40 % of
// the ORB VO's instructions per pair.
//
// Why it can be exact: OpenCV 4 smooths 8-bit images in fixed point. Each direction has integer
// weights w_k (k = -r..r, sum 256), the rows are summed without rounding and the result is rounded once:
//   out = (sum_i sum_j w_i w_j I(y+i, x+j) + 2^15) >> 16.
// Here the column sums V = sum_i w_i I (at most 255 * 256, exact in 16 bits) come first. The row pass
// on NEON multiplies V into 32-bit accumulators (umlal: one instruction per tap and half); on SSE2, which
// has no widening multiply-add, the column sums are stored as U = V - 2^15 (int16) and the row pass uses
// the pairwise multiply-add of signed 16-bit lanes into 32 bits (pmaddwd) on the lanes of x - k and
// x + k interleaved; as the weights sum to 256,
//   out = (sum_j w_j U(x+j) + 2^23 + 2^15) >> 16.
//
// The weights are read from cv::GaussianBlur itself in init() (a vertical line of 255 comes out as
// round(255 w / 256) = w for w <= 128), and init() checks the whole result against cv::GaussianBlur on
// random images of every size it will be given. When OpenCV computes differently (another version, a
// HAL), init() returns false and the caller keeps cv::GaussianBlur: the output never depends on which.
class FixedPointGaussian {
 public:
  static constexpr int kMaxRadiusPx = 10;  // kernels up to 21 taps: sigma up to about 3.3 px

  // False when this OpenCV's blur with `sigma_px` and a kernel of `kernel_px` x `kernel_px` taps (odd;
  // 0: OpenCV's own choice from sigma, 2 * round(3 sigma) + 1 for 8-bit images) cannot be reproduced for
  // every size in `sizes` (CV_8UC1 images of these sizes are what apply() accepts).
  bool init(double sigma_px, int kernel_px, const std::vector<cv::Size>& sizes);

  // `src` CV_8UC1 of an init() size, not a submatrix (cv::GaussianBlur reads a submatrix's surroundings
  // as its border); `dst` another image, (re)allocated only when its size or type differ.
  void apply(const cv::Mat& src, cv::Mat* dst);

  int radiusPx() const { return radius_px_; }

 private:
  bool readWeights();
  bool reproduces(cv::Size size);

  double sigma_px_ = 0.0;
  cv::Size kernel_;  // as given to cv::GaussianBlur
  int radius_px_ = 0;
  std::array<std::uint16_t, kMaxRadiusPx + 1> weight_{};  // weight_[k] for offsets -k and +k
  std::vector<std::uint16_t> sums_;  // one row of column sums with radius_px_ reflected at each end
};

}  // namespace deepnav
