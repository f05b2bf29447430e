#pragma once
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/ximgproc/disparity_filter.hpp>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {

// Parameters of SgbmDisparity (OpenCV StereoSGBM, Hirschmüller 2008, in MODE_SGBM_3WAY).
struct SgbmParams {
  int num_disparities = 64;    // rounded up to a multiple of 16 for OpenCV
  int block_size_px = 5;       // odd
  int p1_per_pixel = 8;        // P1 = p1_per_pixel * channels * block^2: small disparity changes
  int p2_per_pixel = 32;       // P2 = p2_per_pixel * channels * block^2: depth discontinuities
  int disp12_max_diff_px = 1;  // left-right check
  int pre_filter_cap = 63;
  int uniqueness_ratio = 10;  // percent
  int speckle_window_px = 100;
  int speckle_range_px = 2;
  bool wls = false;            // ximgproc weighted-least-squares filter (dense, edge-aware)
  double wls_lambda = 8000.0;  // smoothness strength
  double wls_sigma_color = 1.5;
};

// The widest range OpenCV 4.6's StereoSGBM (MODE_SGBM_3WAY, minDisparity 0) runs with on images
// width_px wide: its searched range (num_disparities rounded up to 16) must stay below the width, else
// compute() throws cv::Exception (core/src/buffer_area.cpp). 0 when no range fits (width <= 16).
inline int sgbmLargestDisparities(int width_px) { return width_px > 16 ? (width_px - 1) / 16 * 16 : 0; }

// Semi-global matching through OpenCV, optionally post-filtered by the ximgproc WLS filter (which
// needs a right-view SGBM as well and returns a disparity everywhere).
class SgbmDisparity final : public DisparityEstimator {
 public:
  // False on a bad parameter, or a range wider than sgbmLargestDisparities(width_px).
  bool init(const SgbmParams& params, int width_px, int height_px);
  bool compute(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity_px) override;

 private:
  bool ready_ = false;
  SgbmParams params_;
  int width_px_ = 0;
  int height_px_ = 0;
  cv::Ptr<cv::StereoSGBM> left_matcher_;
  cv::Ptr<cv::StereoMatcher> right_matcher_;
  cv::Ptr<cv::ximgproc::DisparityWLSFilter> wls_;
  cv::Mat grey_left_, grey_right_;
  cv::Mat fixed_left_, fixed_right_, filtered_;  // CV_16S, disparity * 16
};

}  // namespace deepnav
