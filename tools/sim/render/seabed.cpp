#include "tools/sim/render/seabed.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "tools/sim/normal_rng.h"
#include "tools/sim/render/procedural_noise.h"

namespace deepnav::sim {

namespace {
constexpr float kReliefAmplitude_m = 0.07f;
constexpr float kReliefFullRadius_m = 6.0f;   // full relief inside, flat beyond kHalfExtent - 0.6 m
constexpr float kMarchStep_m = 0.06f;         // horizontal step: 5+ samples per shortest wavelength
constexpr float kFarStepFraction = 0.01f;     // far away, a step of 1 % of the range (8 px at 700 px)
constexpr int kRefineIterations = 6;

float smoothstep01(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}
}  // namespace

bool Seabed::init(std::uint32_t seed) {
  nodes_ = static_cast<int>(std::lround(2.0f * kHalfExtent_m / kCell_m)) + 1;
  height_m_.assign(static_cast<std::size_t>(nodes_) * nodes_, 0.0f);
  const float flat_radius = kHalfExtent_m - 0.6f;
  min_height_m_ = max_height_m_ = 0.0f;
  const cv::Mat relief = fractalNoiseImage(nodes_, nodes_, 2.4f / kCell_m, 3, 0.45f, seed);
  for (int j = 0; j < nodes_; ++j) {
    const float y = -kHalfExtent_m + j * kCell_m;
    for (int i = 0; i < nodes_; ++i) {
      const float x = -kHalfExtent_m + i * kCell_m;
      const float r = std::sqrt(x * x + y * y);
      const float fade = 1.0f - smoothstep01((r - kReliefFullRadius_m) / (flat_radius - kReliefFullRadius_m));
      const float h = kReliefAmplitude_m * fade * relief.at<float>(j, i);
      height_m_[static_cast<std::size_t>(j) * nodes_ + i] = h;
      min_height_m_ = std::min(min_height_m_, h);
      max_height_m_ = std::max(max_height_m_, h);
    }
  }
  // The steepest slope of the bilinear relief: within a cell |grad h| <= |(max |dh/dx|, max |dh/dy|)|
  // over the cell's edges.
  float max_dx = 0.0f, max_dy = 0.0f;
  for (int j = 0; j + 1 < nodes_; ++j) {
    for (int i = 0; i + 1 < nodes_; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * nodes_ + i;
      max_dx = std::max(max_dx, std::abs(height_m_[k + 1] - height_m_[k]));
      max_dy = std::max(max_dy, std::abs(height_m_[k + nodes_] - height_m_[k]));
    }
  }
  max_slope_ = std::sqrt(max_dx * max_dx + max_dy * max_dy) * kInvCell;
  paintTexture(hashU32(seed, 0x5EABEDU, 1));
  return true;
}

float Seabed::heightAt(float x_m, float y_m) const { return sampleHeight(x_m, y_m); }

bool Seabed::intersect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max, float* t,
                       Eigen::Vector3f* n, float hint_t) const {
  Eigen::Vector2f slope;
  if (!intersectSlope(o, d, t_min, t_max, t, &slope, hint_t)) return false;
  if (n) *n = normalOfSlope(slope.x(), slope.y());
  return true;
}

// Flattened: march and refine inlined into it (once per seabed pixel; -5 % instructions per pair).
__attribute__((flatten)) bool Seabed::intersectSlope(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min,
                                                     float t_max, float* t, Eigen::Vector2f* slope,
                                                     float hint_t) const {
  // Reciprocal once: divisions were most of the cost of a seabed pixel.
  const float inv_z = d.z() != 0.0f ? 1.0f / d.z() : INFINITY;
  // The part of the ray inside the slab [min, max height].
  float t0 = t_min, t1 = t_max;
  float entry = -INFINITY, exit = INFINITY;  // where the ray enters and leaves the slab
  if (d.z() < 0.0f) {
    entry = (max_height_m_ - o.z()) * inv_z, exit = (min_height_m_ - o.z()) * inv_z;
    t0 = std::max(t0, entry);
    t1 = std::min(t1, exit);
  } else if (o.z() > max_height_m_) {
    return false;
  }
  if (!(t0 < t1)) return false;
  // The part of it over the relief square; elsewhere the seabed is the plane z = 0.
  float s0 = t0, s1 = t1;
  if (!insideSquare(o, d, t0) || !insideSquare(o, d, t1)) clipToSquare(o, d, &s0, &s1);
  const float t_plane = d.z() != 0.0f ? -o.z() * inv_z : INFINITY;
  const auto flat = [&]() {
    *t = t_plane;
    *slope = Eigen::Vector2f::Zero();
    return true;
  };
  if (!(s0 < s1)) {  // never over the relief
    if (t_plane > t0 && t_plane < t1) return flat();
    return false;
  }
  if (t_plane > t0 && t_plane < s0) return flat();  // flat ground before the relief
  if (march(o, d, s0, s1, s0 == entry, s1 == exit, hint_t, t, slope)) return true;
  if (t_plane > s1 && t_plane < t1) return flat();  // flat ground after it
  return false;
}

bool Seabed::insideSquare(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t) {
  // 1 cm inside: far beyond the rounding of the clipping, which then would leave [s0, s1] unchanged
  // (the square is convex: both ends inside, the whole segment inside); saves its two divisions.
  constexpr float kInside_m = kHalfExtent_m - 0.01f;
  return std::abs(o.x() + t * d.x()) < kInside_m && std::abs(o.y() + t * d.y()) < kInside_m;
}

void Seabed::clipToSquare(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float* s0, float* s1) {
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0f) {
      if (std::abs(o[k]) >= kHalfExtent_m) *s0 = *s1;  // parallel to the square, outside: empty
      continue;
    }
    const float inv = 1.0f / d[k];
    float a = (-kHalfExtent_m - o[k]) * inv, b = (kHalfExtent_m - o[k]) * inv;
    if (a > b) std::swap(a, b);
    *s0 = std::max(*s0, a), *s1 = std::min(*s1, b);
  }
}

bool Seabed::march(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t0, float t1, bool t0_on_slab,
                   bool t1_on_slab, float hint_t, float* t, Eigen::Vector2f* slope) const {
  const auto hitAt = [&](float t_hit) {
    *t = t_hit;
    float h = 0.0f;
    sampleHeightAndSlope(o.x() + t_hit * d.x(), o.y() + t_hit * d.y(), &h, &slope->x(), &slope->y());
    return true;
  };
  if (descendsSteeply(d)) {
    // The ray drops faster than the relief can rise: ray z - h decreases monotonically, so [t0, t1]
    // holds at most one crossing. At the slab's entry (z = max height) the ray is above the relief and
    // at its exit (z = min height) below: no evaluation needed there (decided on t, not on the ray's z,
    // which rounds to either side of the slab's face); elsewhere (clipped by t_min, a nearer hit or
    // the relief square) check the sign where the ray's z does not already tell it.
    // Start from a neighbouring ray's hit when it lies in the bracket, else where the ray meets z = 0.
    if (!t0_on_slab && o.z() + t0 * d.z() < max_height_m_ && above(o, d, t0) <= 0.0f) return hitAt(t0);
    if (!t1_on_slab && o.z() + t1 * d.z() > min_height_m_ && above(o, d, t1) > 0.0f) return false;
    const float start = hint_t > t0 && hint_t < t1 ? hint_t : std::clamp(-o.z() / d.z(), t0, t1);
    return refine(o, d, t0, t1, start, t, slope);
  }
  const float horizontal = std::sqrt(d.x() * d.x() + d.y() * d.y());
  const float inv_horizontal = horizontal > 1e-6f ? 1.0f / horizontal : INFINITY;
  const float descent = -d.z() * inv_horizontal;  // metres down per horizontal metre
  const float length = std::sqrt(horizontal * horizontal + d.z() * d.z());
  // Over a horizontal distance s the gap between ray and relief shrinks by at most (descent + max
  // slope) s: a step of gap / (descent + slope) cannot jump over the surface; never less than the
  // coarse step, whose overshoot the refinement below recovers.
  const float inv_closing = 1.0f / std::max(descent + max_slope_, 1e-3f);
  float ta = t0, fa = above(o, d, ta);
  if (fa <= 0.0f) return hitAt(ta);
  while (ta < t1) {
    const float step_m = std::max(std::max(kMarchStep_m, kFarStepFraction * ta * length), fa * inv_closing);
    const float tb = std::min(ta + step_m * inv_horizontal, t1);
    const float fb = above(o, d, tb);
    if (fb <= 0.0f) return refine(o, d, ta, tb, (ta * fb - tb * fa) / (fb - fa), t, slope);
    ta = tb, fa = fb;
  }
  return false;
}

bool Seabed::descendsSteeply(const Eigen::Vector3f& d) const {
  // descent = -d_z / |d_xy| > max slope, decided on squares (no square root, no division) unless the two
  // are within 1e-4 of each other, where the rounding of the exact form could tip the comparison: then
  // that form, as the march computes it. The same decision, bit for bit.
  const float h2 = d.x() * d.x() + d.y() * d.y(), down = -d.z();
  if (!(down > 0.0f)) return false;
  const float lhs = down * down, rhs = max_slope_ * max_slope_ * h2;
  if (lhs > rhs * 1.0001f) return true;
  if (lhs < rhs * 0.9999f) return false;
  const float horizontal = std::sqrt(h2);
  const float inv_horizontal = horizontal > 1e-6f ? 1.0f / horizontal : INFINITY;
  return down * inv_horizontal > max_slope_;
}

bool Seabed::refine(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float lo, float hi, float start, float* t,
                    Eigen::Vector2f* slope) const {
  // Newton on f(t) = ray z - h with the exact slope of the bilinear relief, kept inside the bracket
  // [lo, hi] (f(lo) > 0 >= f(hi)) by bisecting when a step leaves it; to 0.2 mm in height, or a last
  // Newton step shorter than 0.5 mm along the ray (its residual is second order: micrometres).
  // The normal comes from the slope of the last evaluation (within 0.5 mm of the hit: same patch,
  // or a slope change of a few thousandths across a cell edge).
  float tm = start;
  float hx = 0.0f, hy = 0.0f;
  for (int k = 0; k < kRefineIterations; ++k) {
    float h = 0.0f;
    sampleHeightAndSlope(o.x() + tm * d.x(), o.y() + tm * d.y(), &h, &hx, &hy);
    const float f = o.z() + tm * d.z() - h;
    if (std::abs(f) < 2e-4f) break;
    // |step| < 0.5 mm / |d|, squared: no square root; the division only once the first sample missed
    // (most pixels stop above, from a neighbour's hit).
    const float step_tolerance2 = 2.5e-7f / d.squaredNorm();
    (f > 0.0f ? lo : hi) = tm;
    const float slope = d.z() - hx * d.x() - hy * d.y();
    const float next = slope < 0.0f ? tm - f / slope : 0.5f * (lo + hi);
    if ((next - tm) * (next - tm) < step_tolerance2) {  // a tiny Newton step leaves a negligible residual
      tm = next;
      break;
    }
    tm = next > lo && next < hi ? next : 0.5f * (lo + hi);
  }
  *t = tm;
  *slope = Eigen::Vector2f(hx, hy);
  return true;
}

void Seabed::paintTexture(std::uint32_t seed) {
  texture_.create(kTextureTexels, kTextureTexels, true);
  cv::Mat& img = texture_.base();
  const float texel = kTexturePeriod_m / kTextureTexels;
  // Wrapped noise (cells dividing the texture size), so every pattern tiles with the texture.
  const cv::Mat patches_img = fractalNoiseImage(kTextureTexels, kTextureTexels, 256.0f, 3, 0.5f, seed, true);
  const cv::Mat grain_img = fractalNoiseImage(kTextureTexels, kTextureTexels, 2.0f, 2, 0.6f, seed + 1, true);
  for (int v = 0; v < kTextureTexels; ++v) {
    cv::Vec3b* row = img.ptr<cv::Vec3b>(v);
    for (int u = 0; u < kTextureTexels; ++u) {
      const float x = u * texel, y = v * texel;
      const float patches = patches_img.at<float>(v, u), grain = grain_img.at<float>(v, u);
      const float ripple = std::sin(2.0f * 3.14159265f * (3.0f * x + 1.0f * y + 0.4f * patches) / kTexturePeriod_m * 8.0f);
      const float k = 1.0f + 0.22f * patches + 0.14f * grain + 0.05f * ripple;
      const Eigen::Vector3f sand(0.27f * k, 0.31f * k, 0.34f * k);
      for (int c = 0; c < 3; ++c) row[u][c] = cv::saturate_cast<std::uint8_t>(sand[c] * 255.0f + 0.5f);
    }
  }
  // Pebbles and shell fragments, drawn with their wrapped copies so the texture still tiles.
  NormalRng rng(NormalRng::subSeed(seed, 3));
  for (int i = 0; i < 2500; ++i) {
    const double cx = rng.uniform() * kTextureTexels, cy = rng.uniform() * kTextureTexels;
    const int radius = 1 + static_cast<int>(rng.uniform() * rng.uniform() * 5.0);
    const double shade = rng.uniform();
    const cv::Scalar colour = shade < 0.92 ? cv::Scalar(40 + 30 * shade, 46 + 30 * shade, 50 + 30 * shade)
                                           : cv::Scalar(115, 120, 124);  // a few shell fragments
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        cv::circle(img, cv::Point(static_cast<int>(cx) + dx * kTextureTexels, static_cast<int>(cy) + dy * kTextureTexels),
                   radius, colour, cv::FILLED, cv::LINE_AA);
  }
  texture_.buildMips();
}

}  // namespace deepnav::sim
