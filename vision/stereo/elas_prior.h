#pragma once
#include <opencv2/core.hpp>
#include <vector>

#include "vision/stereo/delaunay_triangulation.h"
#include "vision/stereo/elas_support.h"

namespace deepnav {

// Piecewise-planar disparity prior mu(u, v) of ELAS (Geiger et al. 2010): the Delaunay
// triangulation of the support points, each triangle a plane d = a u + b v + c, rasterised into a
// per-pixel map. The mesh spans the rectangle one pixel outside the image, whose corners take the
// disparity of the nearest support point, so that every pixel is covered. No allocation after
// allocate().
class ElasPrior {
 public:
  bool allocate(int width_px, int height_px, int max_points);
  // view_right: build the prior of the right image, support points moved to (u - d, v).
  // Returns false when there are fewer than 3 support points (no plane at all).
  bool build(const std::vector<SupportPoint>& points, bool view_right);

  // mu in pixels, or a negative value where no triangle covers the pixel.
  const cv::Mat& mean() const { return mean_px_; }
  int triangleCount() const { return triangle_count_; }

 private:
  void addPoint(int u, int v, float d);
  float nearestDisparity(int x, int y) const;
  void rasterise(const float x[3], const float y[3], const float d[3]);

  int width_px_ = 0;
  int height_px_ = 0;
  DelaunayTriangulation mesh_;
  std::vector<float> vertex_d_;  // disparity of each mesh vertex
  std::vector<int> vertex_at_;   // per pixel: the mesh vertex there, or -1
  int triangle_count_ = 0;
  cv::Mat mean_px_;  // CV_32F
};

}  // namespace deepnav
