#pragma once
#include <string>

#include <opencv2/aruco/charuco.hpp>

namespace deepnav {

// A ChArUco calibration target and the acceptance thresholds of its views (target.yaml,
// vision/calib/README.md). Lengths as printed and measured on the physical board.
struct CharucoTarget {
  int squares_x = 8;             // chessboard squares along the board's x
  int squares_y = 6;
  double square_m = 0.06;        // side of one chessboard square
  double marker_m = 0.045;       // side of one ArUco marker (< square_m)
  std::string dictionary = "DICT_5X5_100";
  int min_corners = 12;          // ChArUco corners a view needs, in each camera
  double max_edge_width_px = 3.5;  // views whose edges are wider (blur) are rejected
  double duplicate_px = 4.0;     // views whose corners moved less than this from a kept view are duplicates
  bool fix_k3 = true;            // estimate k1 k2 p1 p2 only (k3 is ill-conditioned without wide views)
};

// False with a message naming the field for an inconsistent target (marker not smaller than its square,
// more markers than the dictionary holds, unknown dictionary).
bool validateCharucoTarget(const CharucoTarget& target, std::string* error);

// The OpenCV 4.6 board of the target (cv::aruco::CharucoBoard::create). Null for an invalid target.
cv::Ptr<cv::aruco::CharucoBoard> makeCharucoBoard(const CharucoTarget& target);

}  // namespace deepnav
