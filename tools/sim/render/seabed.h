#pragma once
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
  // cannot cross it), then the crossing is refined by regula falsi.
  // Outside the relief square the plane z = 0 is hit analytically.
  bool intersect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max, float* t) const;

  float heightAt(float x_m, float y_m) const;
  Eigen::Vector3f normalAt(float x_m, float y_m) const;
  Eigen::Vector3f albedoAt(float x_m, float y_m, float footprint2_m2) const;  // squared pixel size
  float minHeight_m() const { return min_height_m_; }
  float maxHeight_m() const { return max_height_m_; }

 private:
  bool march(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t0, float t1, float* t) const;
  bool refine(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float lo, float flo, float hi, float fhi,
              float* t) const;
  float sampleHeight(float x_m, float y_m) const;
  float above(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t) const;  // ray z - h
  void paintTexture(std::uint32_t seed);

  static constexpr float kHalfExtent_m = 9.6f;  // relief grid covers [-9.6, 9.6]^2
  static constexpr float kCell_m = 0.08f;  // 241 x 241 nodes: heights and slopes stay in L2 cache
  static constexpr float kTexturePeriod_m = 6.4f;
  static constexpr int kTextureTexels = 1024;
  int nodes_ = 0;                // per axis
  std::vector<float> height_m_;  // row-major, y rows
  std::vector<Eigen::Vector2f> slope_;  // (dh/dx, dh/dy) per node, central differences
  float max_slope_ = 0.0f;  // bound on |grad h|, for safe march steps
  float min_height_m_ = 0.0f;
  float max_height_m_ = 0.0f;
  TextureMap texture_;
};

}  // namespace deepnav::sim
