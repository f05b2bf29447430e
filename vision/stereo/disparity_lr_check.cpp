#include "vision/stereo/disparity_lr_check.h"

#include <cmath>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {

void checkLeftRight(const cv::Mat& right_px, float threshold_px, cv::Mat* left_px) {
  const int width = left_px->cols;
  for (int v = 0; v < left_px->rows; ++v) {
    float* left = left_px->ptr<float>(v);
    const float* right = right_px.ptr<float>(v);
    for (int u = 0; u < width; ++u) {
      const float d = left[u];
      if (d < 0.0f) continue;
      const int ur = static_cast<int>(std::lround(static_cast<float>(u) - d));
      const bool ok =
          ur >= 0 && ur < width && right[ur] >= 0.0f && std::fabs(right[ur] - d) <= threshold_px;
      if (!ok) left[u] = kInvalidDisparity;
    }
  }
}

}  // namespace deepnav
