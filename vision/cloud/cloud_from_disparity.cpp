#include "vision/cloud/cloud_from_disparity.h"

namespace deepnav {

bool CloudFromDisparity::init(const StereoGeometry& geometry, const CloudConfig& config,
                              int width_px, int height_px) {
  ready_ = false;
  if (!geometry.isValid() || config.step_px < 1 || config.min_range_m <= 0.0 ||
      config.max_range_m <= config.min_range_m || width_px < config.step_px ||
      height_px < config.step_px) {
    return false;
  }
  geometry_ = geometry;
  config_ = config;
  width_px_ = width_px;
  height_px_ = height_px;
  const int cols = (width_px + config.step_px - 1) / config.step_px;
  const int rows = (height_px + config.step_px - 1) / config.step_px;
  x_per_z_.resize(cols);
  y_per_z_.resize(rows);
  for (int c = 0; c < cols; ++c) {
    x_per_z_[c] = static_cast<float>((c * config.step_px - geometry.cx_px) / geometry.fx_px);
  }
  for (int r = 0; r < rows; ++r) {
    y_per_z_[r] = static_cast<float>((r * config.step_px - geometry.cy_px) / geometry.fy_px);
  }
  ready_ = true;
  return true;
}

bool CloudFromDisparity::allocateCloud(OrganizedCloud* cloud) const {
  if (!ready_ || cloud == nullptr) return false;
  return cloud->allocate(gridRows(), gridCols(), config_.step_px);
}

bool CloudFromDisparity::compute(const cv::Mat& disparity_px, OrganizedCloud* cloud) const {
  if (!ready_ || cloud == nullptr || disparity_px.type() != CV_32FC1 ||
      disparity_px.cols != width_px_ || disparity_px.rows != height_px_ ||
      cloud->rows() != gridRows() || cloud->cols() != gridCols() ||
      cloud->p_point_in_cam_m.type() != CV_32FC3) {
    return false;
  }
  cloud->step_px = config_.step_px;
  const float fb = static_cast<float>(geometry_.focalBaseline());
  // Z in [min, max] <=> d in [fB / max, fB / min]: one comparison pair on d, no division for
  // rejected pixels.
  const float d_min = fb / static_cast<float>(config_.max_range_m);
  const float d_max = fb / static_cast<float>(config_.min_range_m);
  const int step = config_.step_px;
  for (int r = 0; r < gridRows(); ++r) {
    const float* d_row = disparity_px.ptr<float>(r * step);
    cv::Vec3f* p = cloud->row(r);
    const float y_per_z = y_per_z_[r];
    for (int c = 0; c < gridCols(); ++c) {
      const float d = d_row[c * step];
      if (d > 0.0f && d >= d_min && d <= d_max) {
        const float z = fb / d;
        p[c] = cv::Vec3f(x_per_z_[c] * z, y_per_z * z, z);
      } else {
        OrganizedCloud::invalidate(p[c]);
      }
    }
  }
  return true;
}

}  // namespace deepnav
