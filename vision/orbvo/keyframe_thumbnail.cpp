#include "vision/orbvo/keyframe_thumbnail.h"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace deepnav {

void makeThumbnail(const cv::Mat& grey, cv::Mat* scratch, float* out) {
  scratch->create(kThumbnailHeightPx, kThumbnailWidthPx, CV_8UC1);
  cv::resize(grey, *scratch, scratch->size(), 0.0, 0.0, cv::INTER_AREA);
  cv::GaussianBlur(*scratch, *scratch, cv::Size(5, 5), 1.0);
  double sum = 0.0;
  for (int r = 0; r < kThumbnailHeightPx; ++r) {
    const std::uint8_t* row = scratch->ptr<std::uint8_t>(r);
    for (int c = 0; c < kThumbnailWidthPx; ++c) sum += row[c];
  }
  const double mean = sum / kThumbnailSize;
  double squares = 0.0;
  for (int r = 0; r < kThumbnailHeightPx; ++r) {
    const std::uint8_t* row = scratch->ptr<std::uint8_t>(r);
    for (int c = 0; c < kThumbnailWidthPx; ++c) {
      const double d = row[c] - mean;
      out[r * kThumbnailWidthPx + c] = static_cast<float>(d);
      squares += d * d;
    }
  }
  const float scale = squares > 1e-9 ? static_cast<float>(1.0 / std::sqrt(squares)) : 0.0f;
  for (int i = 0; i < kThumbnailSize; ++i) out[i] *= scale;
}

float thumbnailSimilarity(const float* a, const float* b) {
  float dot = 0.0f;
  for (int i = 0; i < kThumbnailSize; ++i) dot += a[i] * b[i];
  return dot;
}

}  // namespace deepnav
