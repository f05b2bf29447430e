#pragma once
#include <opencv2/core.hpp>

namespace deepnav {

// Accuracy of a disparity map against ground truth, over the evaluated pixels (mask != 0 and
// ground truth > 0; Middlebury marks unknown ground truth with 0).
struct StereoAccuracy {
  int evaluated_px = 0;            // pixels counted
  double d1 = 0.0;                 // KITTI D1: fraction with error > 3 px AND > 5 % of the true
                                   // disparity; a pixel without disparity counts as wrong
  double bad1 = 0.0;               // fraction with error > 1 px (missing counts as wrong)
  double coverage = 0.0;           // fraction with a disparity (>= 0)
  double mean_abs_error_px = 0.0;  // over the pixels with a disparity
};

// estimate_px, truth_px: CV_32FC1 of one size; mask: CV_8UC1 of that size, or empty for all pixels.
// Returns a zero StereoAccuracy (evaluated_px == 0) on mismatched inputs.
StereoAccuracy evaluateDisparity(const cv::Mat& estimate_px, const cv::Mat& truth_px,
                                 const cv::Mat& mask);

}  // namespace deepnav
