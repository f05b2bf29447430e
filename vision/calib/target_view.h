#pragma once
#include <vector>

#include <opencv2/core.hpp>

namespace deepnav {

// The corners of a calibration target found in one image, whatever the target (ChArUco, checkerboard).
struct TargetView {
  std::vector<cv::Point2f> corners_px;
  std::vector<int> ids;        // the board's corner ids, ascending (index into the board's corner table)
  int markers = 0;             // ArUco markers detected (ChArUco only)
  double edge_width_px = 0.0;  // blur measure of the board region (see measureEdgeWidth); 0 if no board
};

}  // namespace deepnav
