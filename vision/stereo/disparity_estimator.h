#pragma once
#include <opencv2/core.hpp>

namespace deepnav {

// Disparity maps are CV_32FC1 in pixels, left image as reference: the left pixel (u, v) matches
// the right pixel (u - d, v). A pixel without a disparity holds a negative value
// (kInvalidDisparity); test with `d < 0`. Negative rather than NaN so that integer-minded filters
// and comparisons (d >= 0, std::max) stay well defined.
constexpr float kInvalidDisparity = -1.0f;

// One dense stereo matcher on a rectified pair. Backends: ElasDisparity (own ELAS), SgbmDisparity
// (OpenCV SGBM [+ WLS]); the simulator provides a ground-truth one.
class DisparityEstimator {
 public:
  virtual ~DisparityEstimator() = default;

  // left, right: rectified images of the size the backend was initialised for, CV_8UC1 or
  // CV_8UC3 (BGR). disparity_px receives CV_32FC1 of the same size; it is only (re)allocated when
  // it does not already have that size and type, so a caller keeping it avoids any allocation.
  // Returns false (and leaves *disparity_px unspecified) on bad input or an uninitialised backend.
  virtual bool compute(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity_px) = 0;
};

}  // namespace deepnav
