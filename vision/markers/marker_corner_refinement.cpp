#include "vision/markers/marker_corner_refinement.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace deepnav {

int cornerRefinementHalfWindowPx(const std::vector<cv::Point2f>& corners, int cells_across,
                                 const CornerRefinementConfig& config) {
  double shortest_px = 1e9;
  for (int k = 0; k < 4; ++k) {
    const cv::Point2f d = corners[k] - corners[(k + 1) % 4];
    shortest_px =
        std::min(shortest_px, std::hypot(static_cast<double>(d.x), static_cast<double>(d.y)));
  }
  const int w = static_cast<int>(std::floor(config.window_cells * shortest_px / cells_across));
  return std::clamp(w, 1, config.max_half_window_px);
}

void refineMarkerCorners(const cv::Mat& grey, int cells_across,
                         const CornerRefinementConfig& config, std::vector<cv::Point2f>* corners) {
  if (corners->size() != 4) return;
  const int w = cornerRefinementHalfWindowPx(*corners, cells_across, config);
  const cv::TermCriteria criteria(cv::TermCriteria::MAX_ITER | cv::TermCriteria::EPS,
                                  config.max_iterations, config.min_accuracy_px);
  cv::cornerSubPix(grey, *corners, cv::Size(w, w), cv::Size(-1, -1), criteria);
}

}  // namespace deepnav
