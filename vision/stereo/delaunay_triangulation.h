#pragma once
#include <cstdint>
#include <vector>

namespace deepnav {

// Incremental Delaunay triangulation (Bowyer-Watson) of integer points inside a rectangle, with
// every buffer allocated once: the allocation-free replacement of cv::Subdiv2D for the ELAS prior.
// The rectangle's four corners are the first vertices (0..3); points must lie strictly inside it.
// Predicates are exact (64-bit integer orientation and in-circle tests), so the grid-aligned,
// often co-circular support points of ELAS cannot break it; on co-circular points one of the
// valid Delaunay triangulations is returned.
class DelaunayTriangulation {
 public:
  struct Triangle {
    int v[3];  // vertex indices, (x1 - x0)(y2 - y0) - (y1 - y0)(x2 - x0) > 0
    int n[3];  // n[i]: triangle across edge v[i] -> v[(i + 1) % 3], -1 on the hull
    bool alive;
  };

  // max_points: interior points per triangulation.
  bool allocate(int max_points);
  // Starts a triangulation of the rectangle [x0, x1] x [y0, y1]: x0 < x1, y0 < y1, coordinates
  // within +-16384 (the exact in-circle test then fits 64 bits). False on a bad rectangle.
  bool reset(int x0, int y0, int x1, int y1);
  // Inserts a point strictly inside the rectangle and not yet inserted; returns its vertex
  // index, or -1 when it is outside, a duplicate, or the capacity is exhausted.
  int insert(int x, int y);

  int vertexCount() const { return static_cast<int>(x_.size()); }
  int x(int vertex) const { return x_[vertex]; }
  int y(int vertex) const { return y_[vertex]; }
  // Triangles are slots; skip those not alive.
  int slotCount() const { return static_cast<int>(triangles_.size()); }
  const Triangle& slot(int t) const { return triangles_[t]; }

 private:
  int locate(int x, int y) const;
  bool inCircumcircle(const Triangle& t, int x, int y) const;
  bool collectCavity(int seed, int x, int y);
  int newTriangle(int a, int b, int c);
  void fillCavity(int p);

  struct BoundaryEdge {
    int a, b;     // cavity on the left of a -> b
    int outside;  // triangle across the edge, -1 on the hull
  };

  int x0_ = 0, y0_ = 0, x1_ = 0, y1_ = 0;
  int max_vertices_ = 0;
  int max_triangles_ = 0;
  std::vector<int> x_, y_;
  std::vector<Triangle> triangles_;
  std::vector<int> free_;    // dead slots to reuse
  std::vector<int> cavity_;  // triangles whose circumcircle holds the new point
  std::vector<int> stack_;
  std::vector<std::uint32_t> mark_;  // per slot: stamp of the insertion that visited it
  std::uint32_t stamp_ = 0;
  std::vector<BoundaryEdge> boundary_;
  std::vector<int> starts_at_;  // per vertex: new triangle whose boundary edge starts there
  int last_ = 0;                // start of the next point location walk
};

}  // namespace deepnav
