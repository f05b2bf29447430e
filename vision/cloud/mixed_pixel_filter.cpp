#include "vision/cloud/mixed_pixel_filter.h"

#include <cmath>

namespace deepnav {

bool MixedPixelFilter::init(const MixedPixelConfig& config, int rows, int cols) {
  if (rows <= 0 || cols <= 0 || !(config.min_ray_angle_deg > 0.0) ||
      config.min_ray_angle_deg >= 90.0) {
    return false;
  }
  config_ = config;
  const double c = std::cos(config.min_ray_angle_deg * M_PI / 180.0);
  cos2_max_ = static_cast<float>(c * c);
  mark_.create(rows, cols, CV_8UC1);
  return true;
}

// The segment s = q - p is within the angle of the ray p when (p.s)^2 >= cos^2 |p|^2 |s|^2.
void MixedPixelFilter::markPair(const cv::Vec3f& p, const cv::Vec3f& q, std::uint8_t* mark_p,
                                std::uint8_t* mark_q) const {
  if (!OrganizedCloud::isValid(p) || !OrganizedCloud::isValid(q)) return;
  const cv::Vec3f s = q - p;
  const float ps = p.dot(s);
  if (ps * ps >= cos2_max_ * p.dot(p) * s.dot(s)) {
    *mark_p = 1;
    *mark_q = 1;
  }
}

int MixedPixelFilter::apply(OrganizedCloud* cloud) {
  if (!config_.enabled) return 0;
  if (cloud == nullptr || cloud->rows() != mark_.rows || cloud->cols() != mark_.cols) return -1;
  const int rows = cloud->rows();
  const int cols = cloud->cols();
  for (int r = 0; r < rows; ++r) {
    std::uint8_t* m = mark_.ptr<std::uint8_t>(r);
    for (int c = 0; c < cols; ++c) m[c] = 0;
  }
  // Decide on the unmodified cloud first, remove afterwards: removal must not cascade.
  for (int r = 0; r < rows; ++r) {
    const cv::Vec3f* p = cloud->row(r);
    const cv::Vec3f* below = r + 1 < rows ? cloud->row(r + 1) : nullptr;
    std::uint8_t* m = mark_.ptr<std::uint8_t>(r);
    std::uint8_t* m_below = r + 1 < rows ? mark_.ptr<std::uint8_t>(r + 1) : nullptr;
    for (int c = 0; c < cols; ++c) {
      if (c + 1 < cols) markPair(p[c], p[c + 1], &m[c], &m[c + 1]);
      if (below != nullptr) markPair(p[c], below[c], &m[c], &m_below[c]);
    }
  }
  int removed = 0;
  for (int r = 0; r < rows; ++r) {
    cv::Vec3f* p = cloud->row(r);
    const std::uint8_t* m = mark_.ptr<std::uint8_t>(r);
    for (int c = 0; c < cols; ++c) {
      if (m[c] != 0 && OrganizedCloud::isValid(p[c])) {
        OrganizedCloud::invalidate(p[c]);
        ++removed;
      }
    }
  }
  return removed;
}

}  // namespace deepnav
