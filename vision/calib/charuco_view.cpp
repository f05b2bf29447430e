#include "vision/calib/charuco_view.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <opencv2/imgproc.hpp>

namespace deepnav {
namespace {

// Value below which the given fraction of a CV_32F image's values lie (histogram of 1024 bins).
double percentile(const cv::Mat& values, double max_value, double fraction) {
  constexpr int kBins = 1024;
  std::vector<int> histogram(kBins, 0);
  for (int r = 0; r < values.rows; ++r) {
    const float* row = values.ptr<float>(r);
    for (int c = 0; c < values.cols; ++c) {
      const int bin = std::clamp(static_cast<int>(row[c] / max_value * kBins), 0, kBins - 1);
      ++histogram[bin];
    }
  }
  const double target = fraction * static_cast<double>(values.total());
  double seen = 0.0;
  for (int b = 0; b < kBins; ++b) {
    seen += histogram[b];
    if (seen >= target) return (b + 0.5) * max_value / kBins;
  }
  return max_value;
}

// Median distance from a corner to its nearest neighbour (the square size in pixels, roughly).
double nearestCornerSpacingPx(const std::vector<cv::Point2f>& corners) {
  std::vector<double> nearest;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    double best = 1e9;
    for (std::size_t j = 0; j < corners.size(); ++j)
      if (j != i) best = std::min(best, static_cast<double>(cv::norm(corners[i] - corners[j])));
    nearest.push_back(best);
  }
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}

}  // namespace

double measureEdgeWidth(const cv::Mat& grey, const std::vector<cv::Point2f>& corners_px) {
  if (corners_px.size() < 2) return 0.0;
  const cv::Rect box = cv::boundingRect(corners_px) & cv::Rect(0, 0, grey.cols, grey.rows);
  if (box.width < 8 || box.height < 8) return 0.0;
  cv::Mat roi;
  grey(box).convertTo(roi, CV_32F);
  cv::Mat gx, gy, magnitude;
  // Sobel 3 x 3 weighs the central difference by 8: scale to grey levels per pixel.
  cv::Sobel(roi, gx, CV_32F, 1, 0, 3, 1.0 / 8.0);
  cv::Sobel(roi, gy, CV_32F, 0, 1, 3, 1.0 / 8.0);
  cv::magnitude(gx, gy, magnitude);
  const double contrast = percentile(roi, 256.0, 0.95) - percentile(roi, 256.0, 0.05);
  const double steepest = percentile(magnitude, 256.0, 0.99);
  if (steepest <= 0.0) return 1e9;
  return contrast / steepest;
}

CharucoView detectCharucoView(const cv::Mat& grey, const cv::Ptr<cv::aruco::CharucoBoard>& board) {
  CharucoView view;
  std::vector<std::vector<cv::Point2f>> marker_corners;
  std::vector<int> marker_ids;
  const auto parameters = cv::aruco::DetectorParameters::create();
  cv::aruco::detectMarkers(grey, board->dictionary, marker_corners, marker_ids, parameters);
  view.markers = static_cast<int>(marker_ids.size());
  if (marker_ids.empty()) return view;
  std::vector<cv::Point2f> corners;
  std::vector<int> ids;
  // Without camera parameters the corners are interpolated by local homographies and refined inside
  // interpolateCornersCharuco; on rendered boards OpenCV 4.6 leaves them about +0.5 px off in x and y
  // (tests/unit/calib_charuco_test.cpp), so they are refined again with a window scaled to the squares.
  cv::aruco::interpolateCornersCharuco(marker_corners, marker_ids, grey, board, corners, ids);
  if (corners.size() >= 2) {
    const int half = std::clamp(static_cast<int>(0.1 * nearestCornerSpacingPx(corners)), 2, 8);
    cv::cornerSubPix(grey, corners, cv::Size(half, half), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 50, 0.001));
  }
  std::vector<int> order(ids.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return ids[a] < ids[b]; });
  for (int i : order) {
    view.ids.push_back(ids[i]);
    view.corners_px.push_back(corners[i]);
  }
  view.edge_width_px = measureEdgeWidth(grey, view.corners_px);
  return view;
}

}  // namespace deepnav
