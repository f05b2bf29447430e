#pragma once
#include <vector>

#include <opencv2/aruco/charuco.hpp>

#include "vision/calib/target_view.h"

namespace deepnav {

// The ChArUco corners found in one image (a TargetView whose ids are the board's chessboard corner ids).
using CharucoView = TargetView;

// detectMarkers + interpolateCornersCharuco (OpenCV 4.6 aruco) on a grey image; ids sorted ascending.
// An image without the board gives an empty view (not an error).
CharucoView detectCharucoView(const cv::Mat& grey, const cv::Ptr<cv::aruco::CharucoBoard>& board);

// Width of the board's edges in pixels: contrast (5th to 95th percentile of grey) over the 99th
// percentile of the gradient magnitude, inside the corners' bounding box. A sharp step is about 1-1.5 px
// wide; a Gaussian blur of sigma s makes it about s sqrt(2 pi) = 2.5 s. Independent of distance and
// exposure.
double measureEdgeWidth(const cv::Mat& grey, const std::vector<cv::Point2f>& corners_px);

}  // namespace deepnav
