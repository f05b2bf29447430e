#pragma once
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// Subpixel refinement of the 4 corners of one detected square marker with cv::cornerSubPix, its
// search window sized to the marker's cells. cornerSubPix finds the point where the image gradients
// in the window are orthogonal to the vectors to that point; a window that reaches past the 1-cell
// black border takes in the edges of the inner cells and pulls the corner off (e.g. 2 px on a 17 px
// wide marker with OpenCV 4.6's fixed 11 x 11 window). So the half side is
//   w = clamp(floor(window_cells * s / (n + 2)), 1, max_half_window_px)
// with s the shortest side in px and n + 2 the cells across the marker (n bits plus the border).
struct CornerRefinementConfig {
  double window_cells = 0.6;      // half window as a fraction of one cell, (0, 1]
  int max_half_window_px = 5;     // [1, 20] px
  int max_iterations = 30;        // [1, 1000]
  double min_accuracy_px = 0.01;  // stop when a corner moves less than this, (0, 1] px
};

// corners: the 4 corners of one marker, refined in place. grey: CV_8UC1. cells_across: n + 2.
void refineMarkerCorners(const cv::Mat& grey, int cells_across,
                         const CornerRefinementConfig& config, std::vector<cv::Point2f>* corners);

// The half window w above, px.
int cornerRefinementHalfWindowPx(const std::vector<cv::Point2f>& corners, int cells_across,
                                 const CornerRefinementConfig& config);

}  // namespace deepnav
