#pragma once
#include <opencv2/core.hpp>

namespace deepnav {

// Left-right consistency: a left disparity d at (u, v) survives when the right map at
// (round(u - d), v) is valid and within threshold_px of d; otherwise it becomes invalid (-1).
// Rejects occluded pixels and mismatches, which the two views do not agree on.
void checkLeftRight(const cv::Mat& right_px, float threshold_px, cv::Mat* left_px);

}  // namespace deepnav
