#pragma once
#include <opencv2/core/mat.hpp>

namespace deepnav {

// Halves an 8-bit image (any channel count, even width and height) by 2x2 box averaging with
// round-half-up, (a + b + c + d + 2) >> 2: the values cv::resize gives with INTER_AREA at exactly half
// size (its integer fast path), without the offset table cv::resize allocates on every call. *half must
// already have the size and type (rows / 2, cols / 2, same type); returns false otherwise.
bool halveByArea(const cv::Mat& full, cv::Mat* half);

}  // namespace deepnav
