#include "vision/planes/tile_sums.h"

#include <algorithm>
#include <limits>
#include <opencv2/core/hal/intrin.hpp>

#include "vision/planes/moment_lanes.h"

namespace deepnav {
namespace {

void addScalar(const cv::Vec3f& p, const cv::Vec3f& ref, TileSums* t) {
  const float x = p[0] - ref[0], y = p[1] - ref[1], z = p[2] - ref[2];
  t->n += 1.0f;
  t->sx += x;
  t->sy += y;
  t->sz += z;
  t->sxx += x * x;
  t->sxy += x * y;
  t->sxz += x * z;
  t->syy += y * y;
  t->syz += y * z;
  t->szz += z * z;
}

void merge(const TileSums& o, TileSums* t) {
  t->n += o.n;
  t->sx += o.sx;
  t->sy += o.sy;
  t->sz += o.sz;
  t->sxx += o.sxx;
  t->sxy += o.sxy;
  t->sxz += o.sxz;
  t->syy += o.syy;
  t->syz += o.syz;
  t->szz += o.szz;
}

// Lanes of cells selected by `select(row, col, z)` (a mask of four lanes from column col).
template <class Select, class SelectOne>
TileSums sumSelected(const TileView& tile, const cv::Vec3f& ref, Select select,
                     SelectOne select_one) {
  MomentLanes lanes;
  TileSums tail;
  const cv::v_float32x4 rx = cv::v_setall_f32(ref[0]), ry = cv::v_setall_f32(ref[1]),
                        rz = cv::v_setall_f32(ref[2]);
  for (int r = 0; r < tile.rows; ++r) {
    const cv::Vec3f* p = tile.points + static_cast<std::ptrdiff_t>(r) * tile.stride;
    int c = 0;
    for (; c + 4 <= tile.cols; c += 4) {
      cv::v_float32x4 x, y, z;
      cv::v_load_deinterleave(&p[c][0], x, y, z);
      lanes.add(select(r, c, z), x - rx, y - ry, z - rz);
    }
    for (; c < tile.cols; ++c) {
      if (select_one(r, c, p[c])) addScalar(p[c], ref, &tail);
    }
  }
  TileSums sums = lanes.reduce();
  merge(tail, &sums);
  return sums;
}

}  // namespace

TileSums sumTileLabel(const TileView& tile, const cv::Vec3f& ref, const std::uint8_t* labels,
                      int label_stride, std::uint8_t label) {
  const cv::v_uint32x4 wanted = cv::v_setall_u32(label);
  return sumSelected(
      tile, ref,
      [&](int r, int c, const cv::v_float32x4&) {
        const cv::v_uint32x4 l = cv::v_load_expand_q(labels + r * label_stride + c);
        return cv::v_reinterpret_as_f32(l == wanted);
      },
      [&](int r, int c, const cv::Vec3f&) { return labels[r * label_stride + c] == label; });
}

TileSums sumTile(const TileView& tile, const cv::Vec3f& ref, cv::Vec3f* lo, cv::Vec3f* hi) {
  const float inf = std::numeric_limits<float>::infinity();
  const cv::v_float32x4 v_inf = cv::v_setall_f32(inf), v_ninf = cv::v_setall_f32(-inf);
  const cv::v_float32x4 zero = cv::v_setzero_f32();
  const cv::v_float32x4 rx = cv::v_setall_f32(ref[0]), ry = cv::v_setall_f32(ref[1]),
                        rz = cv::v_setall_f32(ref[2]);
  MomentLanes lanes;
  TileSums tail;
  cv::v_float32x4 lx = v_inf, ly = v_inf, lz = v_inf, hx = v_ninf, hy = v_ninf, hz = v_ninf;
  cv::Vec3f l(inf, inf, inf), h(-inf, -inf, -inf);
  for (int r = 0; r < tile.rows; ++r) {
    const cv::Vec3f* p = tile.points + static_cast<std::ptrdiff_t>(r) * tile.stride;
    int c = 0;
    for (; c + 4 <= tile.cols; c += 4) {
      cv::v_float32x4 x, y, z;
      cv::v_load_deinterleave(&p[c][0], x, y, z);
      const cv::v_float32x4 valid = z > zero;
      lanes.add(valid, x - rx, y - ry, z - rz);
      lx = cv::v_min(lx, cv::v_select(valid, x, v_inf));
      ly = cv::v_min(ly, cv::v_select(valid, y, v_inf));
      lz = cv::v_min(lz, cv::v_select(valid, z, v_inf));
      hx = cv::v_max(hx, cv::v_select(valid, x, v_ninf));
      hy = cv::v_max(hy, cv::v_select(valid, y, v_ninf));
      hz = cv::v_max(hz, cv::v_select(valid, z, v_ninf));
    }
    for (; c < tile.cols; ++c) {
      if (p[c][2] <= 0.0f) continue;
      addScalar(p[c], ref, &tail);
      for (int k = 0; k < 3; ++k) {
        l[k] = std::min(l[k], p[c][k]);
        h[k] = std::max(h[k], p[c][k]);
      }
    }
  }
  *lo = cv::Vec3f(std::min(l[0], cv::v_reduce_min(lx)), std::min(l[1], cv::v_reduce_min(ly)),
                  std::min(l[2], cv::v_reduce_min(lz)));
  *hi = cv::Vec3f(std::max(h[0], cv::v_reduce_max(hx)), std::max(h[1], cv::v_reduce_max(hy)),
                  std::max(h[2], cv::v_reduce_max(hz)));
  TileSums sums = lanes.reduce();
  merge(tail, &sums);
  return sums;
}

void addTileSums(const TileSums& t, const cv::Vec3f& ref, ScatterSums* s) {
  const double dx = ref[0] - s->origin.x(), dy = ref[1] - s->origin.y(),
               dz = ref[2] - s->origin.z();
  const double n = t.n, x = t.sx, y = t.sy, z = t.sz;
  s->n += n;
  s->sx += x + n * dx;
  s->sy += y + n * dy;
  s->sz += z + n * dz;
  s->sxx += t.sxx + 2.0 * dx * x + n * dx * dx;
  s->sxy += t.sxy + dx * y + dy * x + n * dx * dy;
  s->sxz += t.sxz + dx * z + dz * x + n * dx * dz;
  s->syy += t.syy + 2.0 * dy * y + n * dy * dy;
  s->syz += t.syz + dy * z + dz * y + n * dy * dz;
  s->szz += t.szz + 2.0 * dz * z + n * dz * dz;
}

}  // namespace deepnav
