#include "vision/stereo/stereo_accuracy.h"

#include <cmath>

namespace deepnav {

StereoAccuracy evaluateDisparity(const cv::Mat& estimate_px, const cv::Mat& truth_px,
                                 const cv::Mat& mask) {
  StereoAccuracy acc;
  if (estimate_px.type() != CV_32FC1 || truth_px.type() != CV_32FC1 ||
      estimate_px.size() != truth_px.size()) {
    return acc;
  }
  if (!mask.empty() && (mask.type() != CV_8UC1 || mask.size() != truth_px.size())) return acc;
  long d1_bad = 0, bad1 = 0, valid = 0;
  double abs_error_sum = 0.0;
  for (int v = 0; v < truth_px.rows; ++v) {
    const float* est = estimate_px.ptr<float>(v);
    const float* gt = truth_px.ptr<float>(v);
    const std::uint8_t* m = mask.empty() ? nullptr : mask.ptr<std::uint8_t>(v);
    for (int u = 0; u < truth_px.cols; ++u) {
      if ((m != nullptr && m[u] == 0) || !(gt[u] > 0.0f)) continue;
      ++acc.evaluated_px;
      if (!(est[u] >= 0.0f)) {  // also catches NaN
        ++d1_bad;
        ++bad1;
        continue;
      }
      ++valid;
      const double error = std::fabs(static_cast<double>(est[u]) - gt[u]);
      abs_error_sum += error;
      if (error > 3.0 && error > 0.05 * gt[u]) ++d1_bad;
      if (error > 1.0) ++bad1;
    }
  }
  if (acc.evaluated_px == 0) return acc;
  const double n = acc.evaluated_px;
  acc.d1 = d1_bad / n;
  acc.bad1 = bad1 / n;
  acc.coverage = valid / n;
  acc.mean_abs_error_px = valid > 0 ? abs_error_sum / valid : 0.0;
  return acc;
}

}  // namespace deepnav
