#include "vision/stereo/disparity_lr_check.h"

#include <cmath>

#include "vision/stereo/disparity_estimator.h"

namespace deepnav {
namespace {

// std::lround of a float with |x| < 2^31, inline (the libm call was a tenth of the check's cost):
// x - trunc(x) is exact, halves round away from zero.
int roundHalfAway(float x) {
  int i = static_cast<int>(x);
  const float fraction = x - static_cast<float>(i);
  if (fraction >= 0.5f) ++i;
  if (fraction <= -0.5f) --i;
  return i;
}

}  // namespace

void checkLeftRight(const cv::Mat& right_px, float threshold_px, cv::Mat* left_px) {
  const int width = left_px->cols;
  for (int v = 0; v < left_px->rows; ++v) {
    float* left = left_px->ptr<float>(v);
    const float* right = right_px.ptr<float>(v);
    // without a data-dependent branch (about half the pixels of a low-texture frame fail, at random):
    // an invalid or out-of-image match reads column 0 and is rejected by the flags
    for (int u = 0; u < width; ++u) {
      const float d = left[u];
      const int ur = roundHalfAway(static_cast<float>(u) - d);
      const bool inside = d >= 0.0f && ur >= 0 && ur < width;
      const float d_right = right[inside ? ur : 0];
      const bool ok = inside && d_right >= 0.0f && std::fabs(d_right - d) <= threshold_px;
      left[u] = ok ? d : kInvalidDisparity;
    }
  }
}

}  // namespace deepnav
