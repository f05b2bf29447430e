#include "vision/stereo/elas_prior.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace deepnav {

bool ElasPrior::allocate(int width_px, int height_px, int max_points) {
  if (width_px < 2 || height_px < 2 || max_points < 0) return false;
  width_px_ = width_px;
  height_px_ = height_px;
  vertices_.reserve(static_cast<std::size_t>(max_points) + 4);
  triangles_.reserve(2 * (static_cast<std::size_t>(max_points) + 4));
  vertex_d_.create(height_px, width_px, CV_32F);
  vertex_d_.setTo(-1.0f);
  mean_px_.create(height_px, width_px, CV_32F);
  return true;
}

// Two support points may land on one right-image pixel; the larger disparity (the nearer
// surface, which occludes the other) wins.
void ElasPrior::insertPoint(float u, float v, float d) {
  float& slot = vertex_d_.at<float>(static_cast<int>(v), static_cast<int>(u));
  if (slot < 0.0f) vertices_.push_back({u, v, d});
  slot = std::max(slot, d);
}

float ElasPrior::nearestDisparity(float u, float v) const {
  float best_d = 0.0f;
  float best_dist2 = std::numeric_limits<float>::max();
  for (const cv::Point3f& p : vertices_) {
    const float dist2 = (p.x - u) * (p.x - u) + (p.y - v) * (p.y - v);
    if (dist2 < best_dist2) {
      best_dist2 = dist2;
      best_d = vertex_d_.at<float>(static_cast<int>(p.y), static_cast<int>(p.x));
    }
  }
  return best_d;
}

bool ElasPrior::build(const std::vector<SupportPoint>& points, bool view_right) {
  for (const cv::Point3f& p : vertices_) {
    vertex_d_.at<float>(static_cast<int>(p.y), static_cast<int>(p.x)) = -1.0f;
  }
  vertices_.clear();
  triangles_.clear();
  // std::fill rather than Mat::setTo, which allocates a scratch buffer on every call
  std::fill(mean_px_.ptr<float>(0), mean_px_.ptr<float>(0) + mean_px_.total(), -1.0f);
  for (const SupportPoint& p : points) {
    const int u = view_right ? p.u_px - p.d_px : p.u_px;
    if (u < 0) continue;
    insertPoint(static_cast<float>(u), static_cast<float>(p.v_px), static_cast<float>(p.d_px));
  }
  if (vertices_.size() < 3) return false;
  const float right = static_cast<float>(width_px_ - 1);
  const float bottom = static_cast<float>(height_px_ - 1);
  const cv::Point2f corners[4] = {{0, 0}, {right, 0}, {0, bottom}, {right, bottom}};
  float corner_d[4];
  for (int i = 0; i < 4; ++i) corner_d[i] = nearestDisparity(corners[i].x, corners[i].y);
  for (int i = 0; i < 4; ++i) insertPoint(corners[i].x, corners[i].y, corner_d[i]);

  subdiv_.initDelaunay(cv::Rect(0, 0, width_px_, height_px_));
  for (const cv::Point3f& p : vertices_) subdiv_.insert(cv::Point2f(p.x, p.y));
  subdiv_.getTriangleList(triangles_);
  for (const cv::Vec6f& tri : triangles_) rasterise(tri);
  return true;
}

// Plane through the three vertices, written to every pixel whose centre lies in the triangle
// (with a small tolerance so that shared edges leave no cracks). Each row's span is the
// intersection of the three edges' half-planes, so the inner loop only evaluates the plane.
void ElasPrior::rasterise(const cv::Vec6f& tri) {
  const float x[3] = {tri[0], tri[2], tri[4]};
  const float y[3] = {tri[1], tri[3], tri[5]};
  float d[3];
  for (int i = 0; i < 3; ++i)
    d[i] = vertex_d_.at<float>(static_cast<int>(y[i]), static_cast<int>(x[i]));
  const float area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
  if (std::fabs(area) < 1e-3f) return;
  // d = a u + b v + c by Cramer's rule on the three vertices
  const float a = (d[0] * (y[1] - y[2]) + d[1] * (y[2] - y[0]) + d[2] * (y[0] - y[1])) / area;
  const float b = (d[0] * (x[2] - x[1]) + d[1] * (x[0] - x[2]) + d[2] * (x[1] - x[0])) / area;
  const float c = d[0] - a * x[0] - b * y[0];
  constexpr float kTolerancePx = 1e-3f;
  const int v_min =
      std::max(0, static_cast<int>(std::ceil(std::min({y[0], y[1], y[2]}) - kTolerancePx)));
  const int v_max = std::min(
      height_px_ - 1, static_cast<int>(std::floor(std::max({y[0], y[1], y[2]}) + kTolerancePx)));
  for (int v = v_min; v <= v_max; ++v) {
    const float fv = static_cast<float>(v);
    float u_lo = -1e9f, u_hi = 1e9f;
    bool empty = false;
    // Edge i -> j; the inside is where (xj - xi)(fv - yi) - (yj - yi)(u - xi) has the sign of area.
    for (int i = 0; i < 3 && !empty; ++i) {
      const int j = (i + 1) % 3;
      const float ex = x[j] - x[i], ey = y[j] - y[i];
      const float s = area > 0 ? 1.0f : -1.0f;
      // s * (ex (fv - yi) - ey (u - xi)) >= -tol  <=>  s*ey*u <= s*(ex (fv - yi) + ey xi) + tol
      const float k = s * ey;
      const float rhs =
          s * (ex * (fv - y[i]) + ey * x[i]) + kTolerancePx * std::fabs(ey) + kTolerancePx;
      if (std::fabs(k) < 1e-9f) {
        if (rhs < 0.0f) empty = true;
      } else if (k > 0) {
        u_hi = std::min(u_hi, rhs / k);
      } else {
        u_lo = std::max(u_lo, rhs / k);
      }
    }
    if (empty) continue;
    const int u0 = std::max(0, static_cast<int>(std::ceil(u_lo)));
    const int u1 = std::min(width_px_ - 1, static_cast<int>(std::floor(u_hi)));
    float* row = mean_px_.ptr<float>(v);
    const float row_c = b * fv + c;
    for (int u = u0; u <= u1; ++u) row[u] = a * static_cast<float>(u) + row_c;
  }
}

}  // namespace deepnav
