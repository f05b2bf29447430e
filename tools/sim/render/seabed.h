#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "tools/sim/render/texture_map.h"

namespace deepnav::sim {

// The seabed in the panel frame P: z = h(x, y), a smooth procedural relief (value-noise fractal, about
// +-5 cm, wavelengths 0.6 to 2.4 m; finer detail is left to the texture) within relief_radius_m of the panel, fading out smoothly to a flat
// plane z = 0 beyond it, with a tiling procedural sediment texture (sand grain, patches, ripples,
// pebbles). Both from the seed.
class Seabed {
 public:
  bool init(std::uint32_t seed);

  // Nearest hit of o + t d (P) with t in (t_min, t_max): the ray is marched through the slab
  // [min height, max height] with horizontal steps of the larger of 6 cm, 1 % of the range (a pixel
  // covers more than that far away) and the gap to the relief over the closing rate (a step that
  // cannot cross it), then the crossing is refined by Newton steps inside the bracket. A ray descending
  // faster than the steepest relief slope crosses it once: its slab entry and exit go straight to the
  // refinement.
  // Outside the relief square the plane z = 0 is hit analytically.
  // n (optional): the unit normal at the hit, from the slope the refinement already evaluated (saves a
  // second relief lookup in shading). hint_t (optional, > 0): the hit of a neighbouring ray, a better
  // first Newton guess than the mean plane when the ray crosses the relief once (exactness unchanged:
  // the bracket still decides).
  bool intersect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max, float* t,
                 Eigen::Vector3f* n = nullptr, float hint_t = 0.0f) const;
  // The same, giving the relief's slope (dh/dx, dh/dy) at the hit instead of the normal: the renderer
  // normalises (normalOfSlope) four pixels at a time.
  bool intersectSlope(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max, float* t,
                      Eigen::Vector2f* slope, float hint_t) const;
  // The unit normal (-hx, -hy, 1) / |(-hx, -hy, 1)| of a slope: that of the bilinear patch the ray met
  // (its slope changes across cell edges by at most a few thousandths with this gentle relief: no
  // visible facets).
  static Eigen::Vector3f normalOfSlope(float hx, float hy) {
    return Eigen::Vector3f(-hx, -hy, 1.0f) * (1.0f / std::sqrt(1.0f + hx * hx + hy * hy));
  }

  float heightAt(float x_m, float y_m) const;
  // Squared pixel size; B, G, R in lanes 0-2 (TextureMap::sample). Inline: once per seabed pixel.
  Eigen::Vector4f albedoAt(float x_m, float y_m, float footprint2_m2) const {
    constexpr float kTexelsPerM = kTextureTexels / kTexturePeriod_m;
    return texture_.sample(x_m * kTexelsPerM, y_m * kTexelsPerM, footprint2_m2 * kTexelsPerM * kTexelsPerM);
  }
  // The same for four points (lanes) at once (TextureMap::sample4).
  void albedo4(Float4 x_m, Float4 y_m, Float4 footprint2_m2, Eigen::Vector4f out[4]) const {
    constexpr float kTexelsPerM = kTextureTexels / kTexturePeriod_m;
    texture_.sample4(x_m * kTexelsPerM, y_m * kTexelsPerM, footprint2_m2 * kTexelsPerM * kTexelsPerM, out);
  }
  float minHeight_m() const { return min_height_m_; }
  float maxHeight_m() const { return max_height_m_; }

 private:
  // t0_on_slab, t1_on_slab: that end of [t0, t1] is where the ray enters (leaves) the slab, so the ray
  // is above (below) the relief there.
  bool march(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t0, float t1, bool t0_on_slab, bool t1_on_slab,
             float hint_t, float* t, Eigen::Vector2f* slope) const;
  static bool insideSquare(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t);
  static void clipToSquare(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float* s0, float* s1);
  bool descendsSteeply(const Eigen::Vector3f& d) const;  // faster than the steepest relief slope
  bool refine(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float lo, float hi, float start, float* t,
              Eigen::Vector2f* slope) const;
  // The relief grid cell under (x, y): its two rows of corner heights (r0, and r1 one cell further in
  // y), how far across it the point is (ax, ay in [0, 1)), and the heights a, b interpolated along x on
  // either row.
  struct Cell {
    const float* r0;
    const float* r1;
    float ax, ay, a, b;
  };
  bool cellAt(float x_m, float y_m, Cell* c) const;  // false outside the grid
  float sampleHeight(float x_m, float y_m) const;
  // Height and its exact slope (of the bilinear patch) at (x, y).
  void sampleHeightAndSlope(float x_m, float y_m, float* h, float* hx, float* hy) const;
  float above(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t) const {  // ray z - h
    return o.z() + t * d.z() - sampleHeight(o.x() + t * d.x(), o.y() + t * d.y());
  }
  void paintTexture(std::uint32_t seed);

  static constexpr float kHalfExtent_m = 9.6f;  // relief grid covers [-9.6, 9.6]^2
  static constexpr float kCell_m = 0.08f;  // 241 x 241 nodes: heights and slopes stay in L2 cache
  static constexpr float kInvCell = 12.5f;  // 1 / kCell_m: a multiply, not a division, per sample
  static constexpr float kTexturePeriod_m = 6.4f;
  static constexpr int kTextureTexels = 1024;
  int nodes_ = 0;                // per axis
  std::vector<float> height_m_;  // row-major, y rows
  float max_slope_ = 0.0f;  // bound on |grad h|, for safe march steps
  float min_height_m_ = 0.0f;
  float max_height_m_ = 0.0f;
  TextureMap texture_;
};

// Inline: the march calls these a few times per pixel.
inline bool Seabed::cellAt(float x_m, float y_m, Cell* c) const {
  const float gx = (x_m + kHalfExtent_m) * kInvCell, gy = (y_m + kHalfExtent_m) * kInvCell;
  if (!(gx >= 0.0f && gy >= 0.0f && gx < nodes_ - 1 && gy < nodes_ - 1)) return false;
  const int ix = static_cast<int>(gx), iy = static_cast<int>(gy);
  c->ax = gx - ix;
  c->ay = gy - iy;
  c->r0 = &height_m_[static_cast<std::size_t>(iy) * nodes_ + ix];
  c->r1 = c->r0 + nodes_;
  c->a = c->r0[0] + c->ax * (c->r0[1] - c->r0[0]);
  c->b = c->r1[0] + c->ax * (c->r1[1] - c->r1[0]);
  return true;
}

inline float Seabed::sampleHeight(float x_m, float y_m) const {
  Cell c;
  return cellAt(x_m, y_m, &c) ? c.a + c.ay * (c.b - c.a) : 0.0f;
}

inline void Seabed::sampleHeightAndSlope(float x_m, float y_m, float* h, float* hx, float* hy) const {
  Cell c;
  if (!cellAt(x_m, y_m, &c)) {
    *h = *hx = *hy = 0.0f;
    return;
  }
  *h = c.a + c.ay * (c.b - c.a);
  *hx = ((1.0f - c.ay) * (c.r0[1] - c.r0[0]) + c.ay * (c.r1[1] - c.r1[0])) * kInvCell;
  *hy = (c.b - c.a) * kInvCell;
}

}  // namespace deepnav::sim
