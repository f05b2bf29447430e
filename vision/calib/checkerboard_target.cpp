#include "vision/calib/checkerboard_target.h"

namespace deepnav {

bool validateCheckerboardTarget(const CheckerboardTarget& t, std::string* error) {
  auto fail = [&](const std::string& what) {
    if (error) *error = what;
    return false;
  };
  if (t.inner_cols < 3 || t.inner_rows < 3) return fail("inner_corners: at least 3 along each side");
  if (t.inner_cols == t.inner_rows)
    return fail("inner_corners: a square board (" + std::to_string(t.inner_cols) + " x " +
                std::to_string(t.inner_rows) + ") cannot be numbered unambiguously; use one with unequal sides");
  if (!(t.square_m > 0.0)) return fail("square_m must be positive");
  return true;
}

std::vector<cv::Point3f> checkerboardCorners(const CheckerboardTarget& t) {
  std::vector<cv::Point3f> corners;
  corners.reserve(static_cast<std::size_t>(t.inner_cols * t.inner_rows));
  for (int row = 0; row < t.inner_rows; ++row)
    for (int col = 0; col < t.inner_cols; ++col)
      corners.emplace_back(static_cast<float>(col * t.square_m), static_cast<float>(row * t.square_m), 0.0f);
  return corners;
}

}  // namespace deepnav
