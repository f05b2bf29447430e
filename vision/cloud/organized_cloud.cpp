#include "vision/cloud/organized_cloud.h"

namespace deepnav {

bool OrganizedCloud::allocate(int rows, int cols, int step) {
  if (rows <= 0 || cols <= 0 || step <= 0) return false;
  p_point_in_cam_m.create(rows, cols, CV_32FC3);
  p_point_in_cam_m.setTo(cv::Scalar::all(0.0));
  step_px = step;
  return true;
}

int OrganizedCloud::countValid() const {
  int count = 0;
  for (int r = 0; r < rows(); ++r) {
    const cv::Vec3f* p = row(r);
    for (int c = 0; c < cols(); ++c) count += isValid(p[c]) ? 1 : 0;
  }
  return count;
}

}  // namespace deepnav
