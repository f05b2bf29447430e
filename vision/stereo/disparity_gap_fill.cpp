#include "vision/stereo/disparity_gap_fill.h"

#include <algorithm>
#include <cmath>

namespace deepnav {
namespace {

constexpr float kSameSurfacePx = 3.0f;

// Fills the gaps of one line of n samples spaced by `stride` floats.
void fillLine(float* line, int n, int stride, int max_gap_px, bool fill_borders) {
  int last_valid = -1;
  for (int i = 0; i <= n; ++i) {
    if (i < n && line[i * stride] < 0.0f) continue;
    const int gap = i - last_valid - 1;
    if (gap > 0 && gap <= max_gap_px) {
      const bool has_start = last_valid >= 0;
      const bool has_end = i < n;
      if (has_start && has_end) {
        const float d0 = line[last_valid * stride];
        const float d1 = line[i * stride];
        const bool same = std::fabs(d0 - d1) <= kSameSurfacePx;
        for (int k = last_valid + 1; k < i; ++k) {
          const float t = static_cast<float>(k - last_valid) / static_cast<float>(gap + 1);
          line[k * stride] = same ? d0 + t * (d1 - d0) : std::min(d0, d1);
        }
      } else if (fill_borders && (has_start || has_end)) {
        const float d = line[(has_start ? last_valid : i) * stride];
        for (int k = last_valid + 1; k < i; ++k) line[k * stride] = d;
      }
    }
    last_valid = i;
  }
}

}  // namespace

void fillDisparityGaps(int max_gap_px, bool fill_borders, cv::Mat* disparity_px) {
  const int stride = static_cast<int>(disparity_px->step1());
  for (int v = 0; v < disparity_px->rows; ++v) {
    fillLine(disparity_px->ptr<float>(v), disparity_px->cols, 1, max_gap_px, fill_borders);
  }
  for (int u = 0; u < disparity_px->cols; ++u) {
    fillLine(disparity_px->ptr<float>(0) + u, disparity_px->rows, stride, max_gap_px, fill_borders);
  }
}

}  // namespace deepnav
