#include "vision/stereo/elas_prior.h"

#include <algorithm>
#include <cmath>

namespace deepnav {

bool ElasPrior::allocate(int width_px, int height_px, int max_points) {
  if (width_px < 2 || height_px < 2 || max_points < 0 || !mesh_.allocate(max_points)) return false;
  width_px_ = width_px;
  height_px_ = height_px;
  vertex_d_.assign(static_cast<std::size_t>(max_points) + 4, 0.0f);
  vertex_at_.assign(static_cast<std::size_t>(width_px) * height_px, -1);
  mean_px_.create(height_px, width_px, CV_32F);
  return mesh_.reset(-1, -1, width_px, height_px);
}

// Two support points may land on one right-image pixel; the larger disparity (the nearer
// surface, which occludes the other) wins.
void ElasPrior::addPoint(int u, int v, float d) {
  int& at = vertex_at_[static_cast<std::size_t>(v) * width_px_ + u];
  if (at >= 0) {
    vertex_d_[at] = std::max(vertex_d_[at], d);
    return;
  }
  const int vertex = mesh_.insert(u, v);
  if (vertex < 0) return;  // capacity exhausted: cannot happen with max_points grid nodes
  at = vertex;
  vertex_d_[vertex] = d;
}

float ElasPrior::nearestDisparity(int x, int y) const {
  float best_d = 0.0f;
  long best_dist2 = -1;
  for (int i = 4; i < mesh_.vertexCount(); ++i) {
    const long dx = mesh_.x(i) - x, dy = mesh_.y(i) - y;
    const long dist2 = dx * dx + dy * dy;
    if (best_dist2 < 0 || dist2 < best_dist2) {
      best_dist2 = dist2;
      best_d = vertex_d_[i];
    }
  }
  return best_d;
}

bool ElasPrior::build(const std::vector<SupportPoint>& points, bool view_right) {
  for (int i = 4; i < mesh_.vertexCount(); ++i) {
    vertex_at_[static_cast<std::size_t>(mesh_.y(i)) * width_px_ + mesh_.x(i)] = -1;
  }
  mesh_.reset(-1, -1, width_px_, height_px_);
  triangle_count_ = 0;
  // std::fill rather than Mat::setTo, which allocates a scratch buffer on every call
  std::fill(mean_px_.ptr<float>(0), mean_px_.ptr<float>(0) + mean_px_.total(), -1.0f);
  for (const SupportPoint& p : points) {
    const int u = view_right ? p.u_px - p.d_px : p.u_px;
    if (u < 0 || u >= width_px_ || p.v_px < 0 || p.v_px >= height_px_) continue;
    addPoint(u, p.v_px, static_cast<float>(p.d_px));
  }
  if (mesh_.vertexCount() < 4 + 3) return false;
  for (int i = 0; i < 4; ++i) vertex_d_[i] = nearestDisparity(mesh_.x(i), mesh_.y(i));
  for (int t = 0; t < mesh_.slotCount(); ++t) {
    const DelaunayTriangulation::Triangle& tri = mesh_.slot(t);
    if (!tri.alive) continue;
    float x[3], y[3], d[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = static_cast<float>(mesh_.x(tri.v[k]));
      y[k] = static_cast<float>(mesh_.y(tri.v[k]));
      d[k] = vertex_d_[tri.v[k]];
    }
    rasterise(x, y, d);
    ++triangle_count_;
  }
  return true;
}

// Plane through the three vertices, written to every pixel whose centre lies in the triangle
// (with a small tolerance so that shared edges leave no cracks). Each row's span is the
// intersection of the three edges' half-planes, so the inner loop only evaluates the plane.
void ElasPrior::rasterise(const float x[3], const float y[3], const float d[3]) {
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
