#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <set>
#include <utility>

#include "vision/stereo/delaunay_triangulation.h"

namespace deepnav {
namespace {

std::int64_t orient(const DelaunayTriangulation& dt, int a, int b, int c) {
  return static_cast<std::int64_t>(dt.x(b) - dt.x(a)) * (dt.y(c) - dt.y(a)) -
         static_cast<std::int64_t>(dt.y(b) - dt.y(a)) * (dt.x(c) - dt.x(a));
}

// Brute force: every triangle positively oriented, areas summing to the rectangle, neighbour
// links symmetric, and no vertex strictly inside any circumcircle (the Delaunay property).
void expectValidDelaunay(const DelaunayTriangulation& dt, std::int64_t rectangle_area2) {
  std::int64_t area2 = 0;
  for (int t = 0; t < dt.slotCount(); ++t) {
    const auto& tri = dt.slot(t);
    if (!tri.alive) continue;
    const std::int64_t o = orient(dt, tri.v[0], tri.v[1], tri.v[2]);
    ASSERT_GT(o, 0) << "triangle " << t;
    area2 += o;
    for (int i = 0; i < 3; ++i) {
      const int n = tri.n[i];
      if (n < 0) continue;
      ASSERT_TRUE(dt.slot(n).alive);
      bool back = false;
      for (int j = 0; j < 3; ++j) back = back || dt.slot(n).n[j] == t;
      EXPECT_TRUE(back) << "neighbour link " << t << " -> " << n;
    }
    for (int p = 0; p < dt.vertexCount(); ++p) {
      const std::int64_t adx = dt.x(tri.v[0]) - dt.x(p), ady = dt.y(tri.v[0]) - dt.y(p);
      const std::int64_t bdx = dt.x(tri.v[1]) - dt.x(p), bdy = dt.y(tri.v[1]) - dt.y(p);
      const std::int64_t cdx = dt.x(tri.v[2]) - dt.x(p), cdy = dt.y(tri.v[2]) - dt.y(p);
      const std::int64_t det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                               (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                               (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
      ASSERT_LE(det, 0) << "vertex " << p << " inside the circumcircle of triangle " << t;
    }
  }
  EXPECT_EQ(area2, rectangle_area2);
}

TEST(DelaunayTriangulation, RandomPointsGiveAValidTriangulation) {
  DelaunayTriangulation dt;
  ASSERT_TRUE(dt.allocate(400));
  ASSERT_TRUE(dt.reset(-1, -1, 320, 240));
  std::mt19937 rng(3);
  std::set<std::pair<int, int>> used;
  while (used.size() < 300) {
    const int x = static_cast<int>(rng() % 320);
    const int y = static_cast<int>(rng() % 240);
    if (!used.insert({x, y}).second) continue;
    ASSERT_GE(dt.insert(x, y), 0);
  }
  expectValidDelaunay(dt, 321LL * 241LL * 2);
  int alive = 0;
  for (int t = 0; t < dt.slotCount(); ++t) alive += dt.slot(t).alive ? 1 : 0;
  EXPECT_EQ(alive, 2 * dt.vertexCount() - 6);  // Euler, with a 4-vertex hull
}

TEST(DelaunayTriangulation, CoCircularGridPointsAreHandledExactly) {
  // GIVEN the support-point situation: a regular grid with holes (every 4 points co-circular)
  DelaunayTriangulation dt;
  ASSERT_TRUE(dt.allocate(2000));
  ASSERT_TRUE(dt.reset(-1, -1, 200, 150));
  for (int y = 0; y < 150; y += 5) {
    for (int x = 0; x < 200; x += 5) {
      if ((x * 7 + y * 3) % 11 == 0) continue;
      ASSERT_GE(dt.insert(x, y), 0);
    }
  }
  expectValidDelaunay(dt, 201LL * 151LL * 2);
}

TEST(DelaunayTriangulation, RefusesDuplicatesOutsidePointsAndOverflow) {
  DelaunayTriangulation dt;
  ASSERT_TRUE(dt.allocate(2));
  EXPECT_FALSE(dt.reset(10, 0, 5, 5));
  ASSERT_TRUE(dt.reset(0, 0, 10, 10));
  EXPECT_EQ(dt.insert(0, 5), -1);   // on the rectangle: not strictly inside
  EXPECT_EQ(dt.insert(11, 5), -1);  // outside
  EXPECT_EQ(dt.insert(5, 5), 4);
  EXPECT_EQ(dt.insert(5, 5), -1);  // duplicate
  EXPECT_EQ(dt.insert(3, 7), 5);
  EXPECT_EQ(dt.insert(2, 2), -1);  // capacity of 2 interior points
}

}  // namespace
}  // namespace deepnav
