#pragma once
#include <string>

#include <opencv2/core.hpp>

#include "vision/calib/checkerboard_target.h"
#include "vision/calib/target_view.h"

namespace deepnav {

// The inner corners of a checkerboard in one grey image: cv::findChessboardCornersSB (sub-pixel by its own
// fit), all corners or none (an image where the board is cut by the border or hidden in part gives an empty
// view). The corners are numbered in the image's own orientation (id 0 is the corner from which the row,
// id 0 -> inner_cols - 1, runs towards +u and the column, id 0 -> (inner_rows - 1) * inner_cols, towards +v),
// so that like views get like numbers (the duplicate screening). A plain checkerboard is symmetric under
// those flips, which are all valid labellings of a planar grid; the two views of a pair must agree, which
// checkerboardAlignPair sees to.
TargetView detectCheckerboardView(const cv::Mat& grey, const CheckerboardTarget& target);

// Numbers the right view's corners as the left view's: of the four flips of the grid, the one whose row and
// column directions in the image lie nearest the left view's (the two cameras of a rig look the same way,
// so they see the board turned alike). "" when done; why not when even the best flip leaves a direction
// more than 60 deg from the left view's.
std::string checkerboardAlignPair(const TargetView& left, TargetView* right, const CheckerboardTarget& target);

}  // namespace deepnav
