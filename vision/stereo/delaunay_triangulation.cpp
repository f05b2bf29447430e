#include "vision/stereo/delaunay_triangulation.h"

#include <cstdlib>

namespace deepnav {
namespace {

constexpr int kMaxCoordinate = 16384;

// Twice the signed area of (a, b, c): > 0 when c lies left of a -> b (counter-clockwise).
std::int64_t orient(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                    std::int64_t cx, std::int64_t cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

}  // namespace

bool DelaunayTriangulation::allocate(int max_points) {
  if (max_points < 0 || max_points > (1 << 24)) return false;
  max_vertices_ = max_points + 4;
  // a triangulation of n vertices with a 4-vertex hull has 2n - 6 triangles; an insertion frees
  // its cavity before filling it with two more triangles than it had
  max_triangles_ = 2 * max_vertices_ + 8;
  x_.reserve(max_vertices_);
  y_.reserve(max_vertices_);
  triangles_.reserve(max_triangles_);
  free_.reserve(max_triangles_);
  cavity_.reserve(max_triangles_);
  stack_.reserve(max_triangles_);
  boundary_.reserve(3 * static_cast<std::size_t>(max_triangles_));
  mark_.assign(max_triangles_, 0);
  starts_at_.assign(max_vertices_, -1);
  return true;
}

bool DelaunayTriangulation::reset(int x0, int y0, int x1, int y1) {
  if (x0 >= x1 || y0 >= y1 || std::abs(x0) > kMaxCoordinate || std::abs(x1) > kMaxCoordinate ||
      std::abs(y0) > kMaxCoordinate || std::abs(y1) > kMaxCoordinate || max_vertices_ < 4) {
    return false;
  }
  x_.clear();
  y_.clear();
  triangles_.clear();
  free_.clear();
  x0_ = x0;
  y0_ = y0;
  x1_ = x1;
  y1_ = y1;
  // corners 0 (x0, y0), 1 (x1, y0), 2 (x1, y1), 3 (x0, y1); (0, 1, 2) and (0, 2, 3) both have
  // positive orient(), the orientation every triangle keeps
  const int xs[4] = {x0, x1, x1, x0};
  const int ys[4] = {y0, y0, y1, y1};
  for (int i = 0; i < 4; ++i) {
    x_.push_back(xs[i]);
    y_.push_back(ys[i]);
  }
  const int t0 = newTriangle(0, 1, 2);
  const int t1 = newTriangle(0, 2, 3);
  triangles_[t0].n[2] = t1;  // across 2 -> 0
  triangles_[t1].n[0] = t0;  // across 0 -> 2
  last_ = t0;
  return true;
}

int DelaunayTriangulation::newTriangle(int a, int b, int c) {
  int t;
  if (!free_.empty()) {
    t = free_.back();
    free_.pop_back();
  } else {
    t = static_cast<int>(triangles_.size());
    triangles_.push_back(Triangle{});
  }
  triangles_[t] = Triangle{{a, b, c}, {-1, -1, -1}, true};
  return t;
}

// Visibility walk from the last created triangle: cross the first edge that has the point on its
// outer side. Exact orientation tests make it terminate on a Delaunay triangulation; a linear scan
// backs it up all the same. Returns a triangle containing (x, y) (possibly on its boundary).
int DelaunayTriangulation::locate(int x, int y) const {
  auto outside_edge = [&](const Triangle& tri) {
    for (int i = 0; i < 3; ++i) {
      const int a = tri.v[i];
      const int b = tri.v[(i + 1) % 3];
      if (orient(x_[a], y_[a], x_[b], y_[b], x, y) < 0) return i;
    }
    return -1;
  };
  int t = last_;
  for (int steps = 0; steps < max_triangles_; ++steps) {
    const int edge = outside_edge(triangles_[t]);
    if (edge < 0) return t;
    t = triangles_[t].n[edge];
    if (t < 0) break;
  }
  for (int s = 0; s < slotCount(); ++s) {
    if (triangles_[s].alive && outside_edge(triangles_[s]) < 0) return s;
  }
  return -1;
}

// Exact in-circle test of a counter-clockwise triangle: > 0 strictly inside.
bool DelaunayTriangulation::inCircumcircle(const Triangle& t, int x, int y) const {
  const std::int64_t adx = x_[t.v[0]] - x, ady = y_[t.v[0]] - y;
  const std::int64_t bdx = x_[t.v[1]] - x, bdy = y_[t.v[1]] - y;
  const std::int64_t cdx = x_[t.v[2]] - x, cdy = y_[t.v[2]] - y;
  const std::int64_t det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                           (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                           (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return det > 0;
}

// The cavity: the containing triangle and every triangle connected to it whose circumcircle
// strictly contains the point; its boundary edges, cavity on their left.
bool DelaunayTriangulation::collectCavity(int seed, int x, int y) {
  ++stamp_;
  cavity_.clear();
  boundary_.clear();
  stack_.clear();
  stack_.push_back(seed);
  mark_[seed] = stamp_;
  while (!stack_.empty()) {
    const int t = stack_.back();
    stack_.pop_back();
    cavity_.push_back(t);
    for (int i = 0; i < 3; ++i) {
      const int n = triangles_[t].n[i];
      if (n >= 0 && mark_[n] == stamp_) continue;  // already in the cavity
      if (n >= 0 && inCircumcircle(triangles_[n], x, y)) {
        mark_[n] = stamp_;
        stack_.push_back(n);
        continue;
      }
      boundary_.push_back({triangles_[t].v[i], triangles_[t].v[(i + 1) % 3], n});
    }
  }
  // boundary edges whose neighbour later joined the cavity are interior: drop them
  std::size_t kept = 0;
  for (const BoundaryEdge& e : boundary_) {
    if (e.outside >= 0 && mark_[e.outside] == stamp_) continue;
    boundary_[kept++] = e;
  }
  boundary_.resize(kept);
  // the cavity's slots are reused; refuse an insertion that would grow past the reserve
  const std::size_t reusable = free_.size() + cavity_.size();
  const std::size_t fresh = boundary_.size() > reusable ? boundary_.size() - reusable : 0;
  return triangles_.size() + fresh <= static_cast<std::size_t>(max_triangles_);
}

// Star-triangulates the cavity from the new vertex p and stitches the neighbours.
void DelaunayTriangulation::fillCavity(int p) {
  for (int t : cavity_) {
    triangles_[t].alive = false;
    free_.push_back(t);
  }
  for (const BoundaryEdge& e : boundary_) {
    const int t = newTriangle(e.a, e.b, p);
    triangles_[t].n[0] = e.outside;
    if (e.outside >= 0) {
      Triangle& out = triangles_[e.outside];
      for (int j = 0; j < 3; ++j) {
        if (out.v[j] == e.b && out.v[(j + 1) % 3] == e.a) out.n[j] = t;
      }
    }
    starts_at_[e.a] = t;
  }
  for (const BoundaryEdge& e : boundary_) {
    const int t = starts_at_[e.a];
    const int next = starts_at_[e.b];  // (b, c, p): shares b -> p with t as its p -> b
    triangles_[t].n[1] = next;
    triangles_[next].n[2] = t;
  }
  last_ = starts_at_[boundary_.front().a];
}

int DelaunayTriangulation::insert(int x, int y) {
  if (vertexCount() >= max_vertices_ || x <= x0_ || x >= x1_ || y <= y0_ || y >= y1_) return -1;
  const int seed = locate(x, y);
  if (seed < 0) return -1;
  for (int v : triangles_[seed].v) {
    if (x_[v] == x && y_[v] == y) return -1;  // duplicate
  }
  if (!collectCavity(seed, x, y)) return -1;
  const int p = vertexCount();
  x_.push_back(x);
  y_.push_back(y);
  fillCavity(p);
  return p;
}

}  // namespace deepnav
