#include "vision/stereo/elas_disparity.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "vision/stereo/disparity_gap_fill.h"
#include "vision/stereo/disparity_lr_check.h"

namespace deepnav {
namespace {

void addSubpixel(const cv::Mat& subpixel_px, cv::Mat* disparity_px) {
  for (int v = 0; v < disparity_px->rows; ++v) {
    float* d = disparity_px->ptr<float>(v);
    const float* s = subpixel_px.ptr<float>(v);
    for (int u = 0; u < disparity_px->cols; ++u) {
      d[u] = d[u] >= 0.0f ? std::max(0.0f, d[u] + s[u]) : d[u];  // a select, no branch
    }
  }
}

}  // namespace

bool ElasDisparity::init(const ElasParams& params, int width_px, int height_px) {
  ready_ = false;
  if (params.num_disparities < 2 || params.num_disparities > 256) return false;
  params_ = params;
  width_px_ = width_px;
  height_px_ = height_px;
  const int step = std::max(1, params.support_step_px);
  const int max_points = ((width_px - 1) / step + 1) * ((height_px - 1) / step + 1);
  ready_ =
      desc_left_.allocate(width_px, height_px) && desc_right_.allocate(width_px, height_px) &&
      support_.allocate(params, width_px, height_px) &&
      prior_left_.allocate(width_px, height_px, max_points) &&
      prior_right_.allocate(width_px, height_px, max_points) &&
      candidates_left_.allocate(width_px, height_px, params.grid_size_px, params.num_disparities) &&
      candidates_right_.allocate(width_px, height_px, params.grid_size_px,
                                 params.num_disparities) &&
      dense_.allocate(params, width_px) && speckle_.allocate(width_px, height_px) &&
      refiner_.allocate(width_px, height_px, params.num_disparities);
  if (!ready_) return false;
  grey_left_.create(height_px, width_px, CV_8UC1);
  grey_right_.create(height_px, width_px, CV_8UC1);
  disparity_right_px_.create(height_px, width_px, CV_32F);
  subpixel_px_.create(height_px, width_px, CV_32F);
  return true;
}

bool ElasDisparity::toGrey(const cv::Mat& image, cv::Mat* grey) const {
  if (image.rows != height_px_ || image.cols != width_px_) return false;
  if (image.type() == CV_8UC1) {
    image.copyTo(*grey);  // same size and type: no reallocation
  } else if (image.type() == CV_8UC3) {
    cv::cvtColor(image, *grey, cv::COLOR_BGR2GRAY);
  } else {
    return false;
  }
  return true;
}

bool ElasDisparity::compute(const cv::Mat& left, const cv::Mat& right, cv::Mat* disparity_px) {
  if (!ready_ || disparity_px == nullptr) return false;
  if (!toGrey(left, &grey_left_) || !toGrey(right, &grey_right_)) return false;
  // the filters walk the map as one block: a non-continuous view (ROI) is replaced
  if (!disparity_px->isContinuous()) disparity_px->release();
  disparity_px->create(height_px_, width_px_, CV_32F);
  sobel_histogram_.fill(0);
  desc_left_.computeGradients(grey_left_, &sobel_histogram_);
  desc_right_.computeGradients(grey_right_, &sobel_histogram_);
  descriptor_gain_ = descriptorGain(sobel_histogram_, params_.descriptor_target,
                                    params_.max_descriptor_gain, params_.fixed_descriptor_gain);
  desc_left_.computeDescriptors(descriptor_gain_);
  desc_right_.computeDescriptors(descriptor_gain_);
  support_.compute(desc_left_, desc_right_);
  const bool have_left = prior_left_.build(support_.meshPoints(), false);
  const bool have_right = prior_right_.build(support_.meshPoints(), true);
  if (!have_left || !have_right) {
    // nothing could be matched reliably (std::fill: Mat::setTo allocates)
    std::fill(disparity_px->ptr<float>(0), disparity_px->ptr<float>(0) + disparity_px->total(),
              kInvalidDisparity);
    return true;
  }
  candidates_left_.build(support_.points(), false);
  candidates_right_.build(support_.points(), true);
  dense_.match(desc_left_, desc_right_, false, prior_left_.mean(), candidates_left_, disparity_px,
               params_.subpixel ? &subpixel_px_ : nullptr);
  dense_.match(desc_right_, desc_left_, true, prior_right_.mean(), candidates_right_,
               &disparity_right_px_, nullptr);
  postprocess(left, disparity_px);
  return true;
}

// Sec. 4 of the paper, in order; the segment filters run on integer disparities so that sub-pixel
// noise does not split segments, the sub-pixel part is added before interpolation.
void ElasDisparity::postprocess(const cv::Mat& left, cv::Mat* disparity_px) {
  checkLeftRight(disparity_right_px_, static_cast<float>(params_.lr_threshold_px), disparity_px);
  speckle_.apply(params_.speckle_size_px, params_.speckle_sim_px, disparity_px);
  if (params_.subpixel) addSubpixel(subpixel_px_, disparity_px);
  fillDisparityGaps(params_.ipol_gap_width_px, params_.fill_all, disparity_px);
  refiner_.apply(left, params_.refine, disparity_px);
}

}  // namespace deepnav
