#pragma once
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "vision/stereo/elas_support.h"

namespace deepnav {

// Piecewise-planar disparity prior mu(u, v) of ELAS (Geiger et al. 2010): the Delaunay
// triangulation of the support points, each triangle a plane d = a u + b v + c, rasterised into a
// per-pixel map. The four image corners are added with the disparity of the nearest support point
// so that the mesh covers the whole image.
class ElasPrior {
 public:
  bool allocate(int width_px, int height_px, int max_points);
  // view_right: build the prior of the right image, support points moved to (u - d, v).
  // Returns false when there are fewer than 3 support points (no plane at all).
  bool build(const std::vector<SupportPoint>& points, bool view_right);

  // mu in pixels, or a negative value where no triangle covers the pixel.
  const cv::Mat& mean() const { return mean_px_; }
  int triangleCount() const { return static_cast<int>(triangles_.size()); }

 private:
  void insertPoint(float u, float v, float d);
  float nearestDisparity(float u, float v) const;
  void rasterise(const cv::Vec6f& tri);

  int width_px_ = 0;
  int height_px_ = 0;
  cv::Subdiv2D subdiv_;
  std::vector<cv::Vec6f> triangles_;
  std::vector<cv::Point3f> vertices_;  // (u, v, d) of the inserted points
  cv::Mat vertex_d_;                   // CV_32F, disparity at each inserted vertex pixel, else -1
  cv::Mat mean_px_;                    // CV_32F
};

}  // namespace deepnav
