#pragma once
#include <opencv2/core.hpp>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {

// The `gt` backend: serves the true disparity of a frame (the simulator's RenderTruth / FrameTruth
// disparity, the paper's "RGB-D" reference) behind the same interface as ElasDisparity and
// SgbmDisparity, so that the plane chain can be scored with perfect stereo. Pure: the caller hands
// it the truth of the pair before each compute(); the images are only checked for size.
//
//   GtDisparity gt;
//   gt.init(688, 516);
//   gt.setTruth(truth.disparity_px);         // this pair's truth
//   gt.compute(left, right, &disparity_px);  // a copy of it, "no surface" -> kInvalidDisparity
//
// Truth convention: CV_32FC1 in px, 0 (or any value <= 0, or non-finite) where no surface was hit.
// A truth serves one compute() only: a second compute() without setTruth() fails instead of
// silently returning the previous frame's disparity.
class GtDisparity final : public DisparityEstimator {
 public:
  // num_disparities > 0: true disparities at or above it become invalid, as a matcher searching
  // [0, num_disparities) could not find them; 0 keeps every disparity.
  bool init(int width_px, int height_px, int num_disparities = 0);
  // False (and no truth held) when truth is not CV_32FC1 of the configured size. The pixels are
  // shared, not copied: keep them unchanged until compute().
  bool setTruth(const cv::Mat& truth_disparity_px);
  bool compute(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity_px) override;

 private:
  bool ready_ = false;
  int width_px_ = 0;
  int height_px_ = 0;
  float max_disparity_px_ = 0.0f;  // exclusive; 0 = none
  cv::Mat truth_px_;
};

}  // namespace deepnav
