#include "vision/stereo/gt_disparity.h"

#include <cmath>

namespace deepnav {

bool GtDisparity::init(int width_px, int height_px, int num_disparities) {
  ready_ = width_px > 0 && height_px > 0 && num_disparities >= 0;
  width_px_ = width_px;
  height_px_ = height_px;
  max_disparity_px_ = static_cast<float>(num_disparities);
  truth_px_.release();
  return ready_;
}

bool GtDisparity::setTruth(const cv::Mat& truth_disparity_px) {
  truth_px_.release();
  if (!ready_ || truth_disparity_px.type() != CV_32FC1 || truth_disparity_px.cols != width_px_ ||
      truth_disparity_px.rows != height_px_)
    return false;
  truth_px_ = truth_disparity_px;
  return true;
}

bool GtDisparity::compute(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity_px) {
  const cv::Size size(width_px_, height_px_);
  if (!ready_ || truth_px_.empty() || disparity_px == nullptr || left.size() != size || right.size() != size)
    return false;
  disparity_px->create(size, CV_32FC1);
  const bool limited = max_disparity_px_ > 0.0f;
  for (int v = 0; v < height_px_; ++v) {
    const float* in = truth_px_.ptr<float>(v);
    float* out = disparity_px->ptr<float>(v);
    for (int u = 0; u < width_px_; ++u) {
      const float d = in[u];
      const bool valid = std::isfinite(d) && d > 0.0f && (!limited || d < max_disparity_px_);
      out[u] = valid ? d : kInvalidDisparity;
    }
  }
  truth_px_.release();  // one frame's truth serves one compute()
  return true;
}

}  // namespace deepnav
