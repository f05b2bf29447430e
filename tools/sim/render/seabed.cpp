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
  slope_.assign(height_m_.size(), Eigen::Vector2f::Zero());
  for (int j = 1; j + 1 < nodes_; ++j) {
    for (int i = 1; i + 1 < nodes_; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * nodes_ + i;
      slope_[k] = Eigen::Vector2f(height_m_[k + 1] - height_m_[k - 1], height_m_[k + nodes_] - height_m_[k - nodes_]) /
                  (2.0f * kCell_m);
    }
  }
  max_slope_ = 0.0f;
  for (const Eigen::Vector2f& g : slope_) max_slope_ = std::max(max_slope_, g.norm());
  max_slope_ *= 1.1f;  // bilinear interpolation between nodes can be a little steeper than the nodes
  paintTexture(hashU32(seed, 0x5EABEDU, 1));
  return true;
}

float Seabed::heightAt(float x_m, float y_m) const { return sampleHeight(x_m, y_m); }

inline float Seabed::sampleHeight(float x_m, float y_m) const {
  const float gx = (x_m + kHalfExtent_m) / kCell_m, gy = (y_m + kHalfExtent_m) / kCell_m;
  if (!(gx >= 0.0f && gy >= 0.0f && gx < nodes_ - 1 && gy < nodes_ - 1)) return 0.0f;
  const int ix = static_cast<int>(gx), iy = static_cast<int>(gy);
  const float ax = gx - ix, ay = gy - iy;
  const float* r0 = &height_m_[static_cast<std::size_t>(iy) * nodes_ + ix];
  const float* r1 = r0 + nodes_;
  const float a = r0[0] + ax * (r0[1] - r0[0]);
  const float b = r1[0] + ax * (r1[1] - r1[0]);
  return a + ay * (b - a);
}

Eigen::Vector3f Seabed::normalAt(float x_m, float y_m) const {
  const float gx = (x_m + kHalfExtent_m) / kCell_m, gy = (y_m + kHalfExtent_m) / kCell_m;
  if (!(gx >= 0.0f && gy >= 0.0f && gx < nodes_ - 1 && gy < nodes_ - 1)) return Eigen::Vector3f::UnitZ();
  const int ix = static_cast<int>(gx), iy = static_cast<int>(gy);
  const float ax = gx - ix, ay = gy - iy;
  const Eigen::Vector2f* r0 = &slope_[static_cast<std::size_t>(iy) * nodes_ + ix];
  const Eigen::Vector2f* r1 = r0 + nodes_;
  const Eigen::Vector2f a = r0[0] + ax * (r0[1] - r0[0]);
  const Eigen::Vector2f b = r1[0] + ax * (r1[1] - r1[0]);
  const Eigen::Vector2f g = a + ay * (b - a);
  return Eigen::Vector3f(-g.x(), -g.y(), 1.0f).normalized();
}

Eigen::Vector3f Seabed::albedoAt(float x_m, float y_m, float footprint2_m2) const {
  constexpr float kTexelsPerM = kTextureTexels / kTexturePeriod_m;
  return texture_.sample(x_m * kTexelsPerM, y_m * kTexelsPerM, footprint2_m2 * kTexelsPerM * kTexelsPerM);
}

float Seabed::above(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t) const {
  return o.z() + t * d.z() - sampleHeight(o.x() + t * d.x(), o.y() + t * d.y());
}

bool Seabed::intersect(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t_min, float t_max,
                       float* t) const {
  // Reciprocals once: divisions were most of the cost of a seabed pixel.
  const Eigen::Vector3f inv(d.x() != 0.0f ? 1.0f / d.x() : INFINITY, d.y() != 0.0f ? 1.0f / d.y() : INFINITY,
                            d.z() != 0.0f ? 1.0f / d.z() : INFINITY);
  // The part of the ray inside the slab [min, max height].
  float t0 = t_min, t1 = t_max;
  if (d.z() < 0.0f) {
    t0 = std::max(t0, (max_height_m_ - o.z()) * inv.z());
    t1 = std::min(t1, (min_height_m_ - o.z()) * inv.z());
  } else if (o.z() > max_height_m_) {
    return false;
  }
  if (!(t0 < t1)) return false;
  // The part of it over the relief square; elsewhere the seabed is the plane z = 0.
  float s0 = t0, s1 = t1;
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0.0f) {
      if (std::abs(o[k]) >= kHalfExtent_m) s0 = s1 = t1;
      continue;
    }
    float a = (-kHalfExtent_m - o[k]) * inv[k], b = (kHalfExtent_m - o[k]) * inv[k];
    if (a > b) std::swap(a, b);
    s0 = std::max(s0, a), s1 = std::min(s1, b);
  }
  const float t_plane = d.z() != 0.0f ? -o.z() * inv.z() : INFINITY;
  if (!(s0 < s1)) {  // never over the relief
    if (t_plane > t0 && t_plane < t1) return *t = t_plane, true;
    return false;
  }
  if (t_plane > t0 && t_plane < s0) return *t = t_plane, true;  // flat ground before the relief
  if (march(o, d, s0, s1, t)) return true;
  if (t_plane > s1 && t_plane < t1) return *t = t_plane, true;  // flat ground after it
  return false;
}

bool Seabed::march(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float t0, float t1, float* t) const {
  const float horizontal = std::sqrt(d.x() * d.x() + d.y() * d.y());
  if (!(horizontal > 1e-6f)) {  // straight down: one bracket, the whole segment
    return refine(o, d, t0, above(o, d, t0), t1, above(o, d, t1), t);
  }
  const float inv_horizontal = 1.0f / horizontal;
  const float length = std::sqrt(horizontal * horizontal + d.z() * d.z());
  // Over a horizontal distance s the gap between ray and relief shrinks by at most (descent + max
  // slope) s: a step of gap / (descent + slope) cannot jump over the surface; never less than the
  // coarse step, whose overshoot the refinement below recovers.
  const float inv_closing = 1.0f / std::max(-d.z() * inv_horizontal + max_slope_, 1e-3f);
  float ta = t0, fa = above(o, d, ta);
  if (fa <= 0.0f) return *t = ta, true;
  while (ta < t1) {
    const float step_m = std::max(std::max(kMarchStep_m, kFarStepFraction * ta * length), fa * inv_closing);
    const float tb = std::min(ta + step_m * inv_horizontal, t1);
    const float fb = above(o, d, tb);
    if (fb <= 0.0f) return refine(o, d, ta, fa, tb, fb, t);
    ta = tb, fa = fb;
  }
  return false;
}

bool Seabed::refine(const Eigen::Vector3f& o, const Eigen::Vector3f& d, float lo, float flo, float hi, float fhi,
                    float* t) const {
  if (flo <= 0.0f) return *t = lo, true;
  if (fhi > 0.0f) return false;
  // Illinois regula falsi on [lo, hi], flo > 0 >= fhi, to 0.1 mm in height.
  int side = 0;
  for (int k = 0; k < kRefineIterations; ++k) {
    const float tm = (lo * fhi - hi * flo) / (fhi - flo);
    const float fm = above(o, d, tm);
    if (std::abs(fm) < 1e-4f) return *t = tm, true;
    if (fm > 0.0f) {
      lo = tm, flo = fm;
      if (side == 1) fhi *= 0.5f;
      side = 1;
    } else {
      hi = tm, fhi = fm;
      if (side == -1) flo *= 0.5f;
      side = -1;
    }
  }
  *t = (lo * fhi - hi * flo) / (fhi - flo);
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
    const cv::Scalar colour = shade < 0.7 ? cv::Scalar(40 + 30 * shade, 46 + 30 * shade, 50 + 30 * shade)
                                          : cv::Scalar(150, 160, 165);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        cv::circle(img, cv::Point(static_cast<int>(cx) + dx * kTextureTexels, static_cast<int>(cy) + dy * kTextureTexels),
                   radius, colour, cv::FILLED, cv::LINE_AA);
  }
  texture_.buildMips();
}

}  // namespace deepnav::sim
