#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace deepnav {

// A plain checkerboard calibration target (target.yaml with `type: checkerboard`, vision/calib/README.md).
// Its corners are the inner corners, where four squares meet; a view counts only when all of them are
// found (a board seen in part is rejected: without markers the corners could not be numbered).
struct CheckerboardTarget {
  int inner_cols = 9;              // inner corners along a row (OpenCV's pattern width)
  int inner_rows = 6;              // inner corners along a column
  double square_m = 0.025;         // side of one square, as measured
  double max_edge_width_px = 3.5;  // views whose edges are wider (blur) are rejected
  double duplicate_px = 4.0;       // views whose corners moved less than this from a kept view are duplicates
  bool fix_k3 = true;              // estimate k1 k2 p1 p2 only
};

// False with a message naming the field: fewer than 3 corners along a side, a square board (its
// numbering would be ambiguous by quarter turns), a non-positive square.
bool validateCheckerboardTarget(const CheckerboardTarget& target, std::string* error);

// The inner corners in the board's frame (metres, z = 0), row by row: id = row * inner_cols + col.
std::vector<cv::Point3f> checkerboardCorners(const CheckerboardTarget& target);

}  // namespace deepnav
