#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>

#include "vision/planes/scatter_sums.h"

namespace deepnav {

// First and second moments of the points of one tile (a small rectangle of an organised cloud),
// in float relative to a reference point of the tile: within a tile the coordinates are
// centimetres, so float sums lose nothing the plane tests can see, and four cells are summed at
// a time (OpenCV universal intrinsics: SSE2 on x86-64, NEON on aarch64).
struct TileSums {
  float n = 0.0f;
  float sx = 0.0f, sy = 0.0f, sz = 0.0f;
  float sxx = 0.0f, sxy = 0.0f, sxz = 0.0f, syy = 0.0f, syz = 0.0f, szz = 0.0f;
};

// The cells of one tile: rows x cols cells from `points`, row stride `stride` cells.
struct TileView {
  const cv::Vec3f* points = nullptr;
  int stride = 0;
  int rows = 0;
  int cols = 0;
};

// Sums of the valid cells (z > 0) of the tile, relative to ref; *lo, *hi: the bounding box of
// their points (lo > hi when there are none).
TileSums sumTile(const TileView& tile, const cv::Vec3f& ref, cv::Vec3f* lo, cv::Vec3f* hi);
// Sums of the cells whose label (same layout as the points, stride label_stride) equals label.
TileSums sumTileLabel(const TileView& tile, const cv::Vec3f& ref, const std::uint8_t* labels,
                      int label_stride, std::uint8_t label);

// Adds the tile's sums (relative to ref) to *sums (relative to sums->origin), in double:
// q = (p - ref) + delta with delta = ref - origin.
void addTileSums(const TileSums& tile, const cv::Vec3f& ref, ScatterSums* sums);

// Sum of Z^2 (camera depth) over the tile's points, from its sums: Z = z + ref_z.
inline double sumDepthSquared(const TileSums& t, const cv::Vec3f& ref) {
  const double rz = ref[2];
  return static_cast<double>(t.szz) + 2.0 * rz * t.sz + t.n * rz * rz;
}

}  // namespace deepnav
