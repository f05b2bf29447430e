#pragma once
#include <opencv2/core.hpp>

namespace deepnav {

// An organised point cloud: one 3D point per cell of a regular grid over the left image.
// Cell (row, col) is the image pixel (u, v) = (col * step_px, row * step_px). Points are in the
// camera optical frame C, metres. A cell without a point holds (0, 0, 0): valid points have
// z > 0 (they lie in front of the camera), so `p[2] > 0` is the one validity test.
struct OrganizedCloud {
  cv::Mat p_point_in_cam_m;  // CV_32FC3, rows x cols of the grid
  int step_px = 1;

  // Sizes the buffer once (start-up). Returns false for non-positive sizes.
  bool allocate(int rows, int cols, int step);

  int rows() const { return p_point_in_cam_m.rows; }
  int cols() const { return p_point_in_cam_m.cols; }
  const cv::Vec3f* row(int r) const { return p_point_in_cam_m.ptr<cv::Vec3f>(r); }
  cv::Vec3f* row(int r) { return p_point_in_cam_m.ptr<cv::Vec3f>(r); }

  static bool isValid(const cv::Vec3f& p) { return p[2] > 0.0f; }
  static void invalidate(cv::Vec3f& p) { p = cv::Vec3f(0.0f, 0.0f, 0.0f); }
  int countValid() const;
};

}  // namespace deepnav
