#pragma once
#include <string>

namespace deepnav {

// Whether a dense-stereo disparity range can run on images of width_px (at the matching size, i.e. after
// vision.dense_scale_down). method: "elas", "sgbm" or "sgbm-wls".
//
// OpenCV 4.6's StereoSGBM (MODE_SGBM_3WAY, minDisparity 0, as vision/stereo/sgbm_disparity.cpp makes it)
// throws from compute() (an assertion in core/src/buffer_area.cpp, which reaches std::terminate when it
// escapes a worker thread) whenever the width is at most numDisparities rounded up to a multiple of 16.
// Measured on every width from 16 to N + 30 for N = 16, 32, 48, 64, 128, 256, block sizes 1, 5 and 11,
// the left matcher and the WLS right matcher alike: the first width that works is always N16 + 1, for
// any height, P1, P2. ELAS (vision/stereo/elas_disparity.cpp) does not fail there, but a range that
// reaches the width searches disparities no pixel can have (u - d < 0 for every column u), so the same
// bound, without the rounding, is asked of it.
//
// False with *why saying the largest range the width admits.
bool denseStereoRangeFits(const std::string& method, int width_px, int num_disparities, std::string* why);

// The disparity range OpenCV's SGBM actually searches: num_disparities rounded up to a multiple of 16.
int sgbmSearchedDisparities(int num_disparities);

}  // namespace deepnav
