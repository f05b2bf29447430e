#include "vision/calib/checkerboard_view.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <opencv2/calib3d.hpp>

#include "vision/calib/charuco_view.h"

namespace deepnav {
namespace {

cv::Point2f rowDirection(const std::vector<cv::Point2f>& c, int cols) { return c[cols - 1] - c[0]; }
cv::Point2f columnDirection(const std::vector<cv::Point2f>& c, int cols, int rows) {
  return c[static_cast<std::size_t>((rows - 1) * cols)] - c[0];
}

// Re-numbers the corners (row-major, inner_cols per row) by the flips of the grid that make the row run
// towards +u and the column towards +v.
void orientInImage(std::vector<cv::Point2f>* corners, int cols, int rows) {
  if (rowDirection(*corners, cols).x < 0.0f)
    for (int r = 0; r < rows; ++r) std::reverse(corners->begin() + r * cols, corners->begin() + (r + 1) * cols);
  if (columnDirection(*corners, cols, rows).y < 0.0f)
    for (int r = 0; r < rows / 2; ++r)
      std::swap_ranges(corners->begin() + r * cols, corners->begin() + (r + 1) * cols,
                       corners->begin() + (rows - 1 - r) * cols);
}

}  // namespace

TargetView detectCheckerboardView(const cv::Mat& grey, const CheckerboardTarget& target) {
  TargetView view;
  std::vector<cv::Point2f> corners;
  const cv::Size pattern(target.inner_cols, target.inner_rows);
  // Not CALIB_CB_EXHAUSTIVE: on the opencv-doc stereo set it lost 1 of 26 boards and took 1.3 times as long.
  const int flags = cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_ACCURACY;
  if (!cv::findChessboardCornersSB(grey, pattern, corners, flags) ||
      corners.size() != static_cast<std::size_t>(target.inner_cols * target.inner_rows))
    return view;
  orientInImage(&corners, target.inner_cols, target.inner_rows);
  view.corners_px = std::move(corners);
  view.ids.resize(view.corners_px.size());
  std::iota(view.ids.begin(), view.ids.end(), 0);
  view.edge_width_px = measureEdgeWidth(grey, view.corners_px);
  return view;
}

std::string checkerboardAlignPair(const TargetView& left, TargetView* right, const CheckerboardTarget& target) {
  const int cols = target.inner_cols, rows = target.inner_rows;
  if (left.corners_px.size() != right->corners_px.size() || left.corners_px.empty()) return "";
  const auto cosine = [](cv::Point2f a, cv::Point2f b) { return a.dot(b) / std::sqrt(a.dot(a) * b.dot(b) + 1e-12f); };
  const cv::Point2f row_left = rowDirection(left.corners_px, cols),
                    column_left = columnDirection(left.corners_px, cols, rows);
  std::vector<cv::Point2f> best;
  float best_score = -2.0f;
  for (int flip = 0; flip < 4; ++flip) {
    std::vector<cv::Point2f> c = right->corners_px;
    if (flip & 1)
      for (int r = 0; r < rows; ++r) std::reverse(c.begin() + r * cols, c.begin() + (r + 1) * cols);
    if (flip & 2)
      for (int r = 0; r < rows / 2; ++r)
        std::swap_ranges(c.begin() + r * cols, c.begin() + (r + 1) * cols, c.begin() + (rows - 1 - r) * cols);
    const float score =
        std::min(cosine(row_left, rowDirection(c, cols)), cosine(column_left, columnDirection(c, cols, rows)));
    if (score > best_score) {
      best_score = score;
      best = std::move(c);
    }
  }
  if (best_score < 0.5f)
    return "the two cameras see the board turned more than 60 deg from each other: cannot number it alike";
  right->corners_px = std::move(best);
  return "";
}

}  // namespace deepnav
