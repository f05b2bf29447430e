#include "vision/stereo/sgbm_disparity.h"

#include <opencv2/imgproc.hpp>

namespace deepnav {

namespace {

const cv::Mat& toGrey(const cv::Mat& image, cv::Mat* grey) {
  if (image.channels() == 1) return image;
  cv::cvtColor(image, *grey, cv::COLOR_BGR2GRAY);
  return *grey;
}

}  // namespace

bool SgbmDisparity::init(const SgbmParams& params, int width_px, int height_px) {
  ready_ = false;
  if (width_px < 16 || height_px < 16 || params.num_disparities < 1 || params.block_size_px < 1 ||
      params.block_size_px % 2 == 0) {
    return false;
  }
  params_ = params;
  params_.num_disparities = (params.num_disparities + 15) / 16 * 16;
  // OpenCV would throw from compute(), on some sizes from a destructor (std::terminate, uncatchable).
  if (params_.num_disparities > sgbmLargestDisparities(width_px)) return false;
  width_px_ = width_px;
  height_px_ = height_px;
  const int area = params.block_size_px * params.block_size_px;
  // Matching runs on grey images (P1, P2 for one channel); colour only guides the WLS filter.
  left_matcher_ = cv::StereoSGBM::create(0, params_.num_disparities, params.block_size_px,
                                         params.p1_per_pixel * area, params.p2_per_pixel * area,
                                         params.disp12_max_diff_px, params.pre_filter_cap,
                                         params.uniqueness_ratio, params.speckle_window_px,
                                         params.speckle_range_px, cv::StereoSGBM::MODE_SGBM_3WAY);
  if (params.wls) {
    wls_ = cv::ximgproc::createDisparityWLSFilter(left_matcher_);
    wls_->setLambda(params.wls_lambda);
    wls_->setSigmaColor(params.wls_sigma_color);
    right_matcher_ = cv::ximgproc::createRightMatcher(left_matcher_);
  }
  grey_left_.create(height_px, width_px, CV_8UC1);
  grey_right_.create(height_px, width_px, CV_8UC1);
  fixed_left_.create(height_px, width_px, CV_16S);
  fixed_right_.create(height_px, width_px, CV_16S);
  filtered_.create(height_px, width_px, CV_16S);
  ready_ = true;
  return true;
}

bool SgbmDisparity::compute(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity_px) {
  if (!ready_ || disparity_px == nullptr) return false;
  if (left.size() != cv::Size(width_px_, height_px_) || right.size() != left.size() ||
      left.type() != right.type() || (left.type() != CV_8UC1 && left.type() != CV_8UC3)) {
    return false;
  }
  const cv::Mat& grey_left = toGrey(left, &grey_left_);
  const cv::Mat& grey_right = toGrey(right, &grey_right_);
  left_matcher_->compute(grey_left, grey_right, fixed_left_);
  const cv::Mat* fixed = &fixed_left_;
  if (params_.wls) {
    right_matcher_->compute(grey_right, grey_left, fixed_right_);
    wls_->filter(fixed_left_, left, filtered_, fixed_right_);
    fixed = &filtered_;
  }
  // OpenCV marks unmatched pixels with (minDisparity - 1) * 16 = -16: negative stays invalid.
  fixed->convertTo(*disparity_px, CV_32F, 1.0 / 16.0);
  cv::max(*disparity_px, kInvalidDisparity, *disparity_px);
  return true;
}

}  // namespace deepnav
