#include "tools/sim/render/forward_scatter.h"

#include <algorithm>
#include <cmath>

#include "tools/sim/render/float4_exp.h"

namespace deepnav::sim {

void ForwardScatter::init(int width_px, int height_px, int channels, float fx_px, const WaterEffects& effects) {
  width_ = width_px, height_ = height_px, channels_ = channels;
  px_per_m_ = fx_px * effects.forward_scatter_rad_per_m;
  std::array<float, 3> b = effects.forward_scatter_per_m;
  if (channels == 1) b = {b[1], b[1], b[1]};  // grey: mostly green (0.587 G)
  forward_grey_per_m_ = b[0];
  // Ranges up to the renderer's 40 m.
  scattered_.resize(static_cast<std::size_t>(40.0f / kStep_m) + 2);
  for (std::size_t i = 0; i < scattered_.size(); ++i) {
    const double x = static_cast<double>(i) * kStep_m;
    for (int c = 0; c < 3; ++c) scattered_[i][c] = static_cast<float>(1.0 - std::exp(-b[c] * x));
    scattered_[i][3] = 0.0f;
  }
  int w = width_px, h = height_px;
  for (int l = 1; l <= kLevels; ++l) {
    w = (w + 1) / 2, h = (h + 1) / 2;
    levels_[l].width = w, levels_[l].height = h;
    levels_[l].data.assign(static_cast<std::size_t>(w) * h * channels, 0.0f);
    levels_[l].wide.assign(static_cast<std::size_t>(width_px) * h * channels, 0.0f);
  }
  const std::size_t row = static_cast<std::size_t>(width_px) * channels;
  level_row_.assign(row, 0.0f);
  blurred_row_.assign(row, 0.0f);
  tent_.assign(static_cast<std::size_t>(width_px), 0.0f);
  level_map_.assign(static_cast<std::size_t>(width_px) * height_px, 0.0f);
}

void ForwardScatter::reduce(const float* in, int in_w, int in_h, Level* out) const {
  // 2 x 2 means; an odd last row or column repeats itself.
  const int c = channels_;
  for (int y = 0; y < out->height; ++y) {
    const float* r0 = in + static_cast<std::size_t>(2 * y) * in_w * c;
    const float* r1 = in + static_cast<std::size_t>(std::min(2 * y + 1, in_h - 1)) * in_w * c;
    float* o = out->data.data() + static_cast<std::size_t>(y) * out->width * c;
    for (int x = 0; x < out->width; ++x) {
      const int x0 = 2 * x * c, x1 = std::min(2 * x + 1, in_w - 1) * c;
      for (int k = 0; k < c; ++k) o[x * c + k] = 0.25f * ((r0[x0 + k] + r0[x1 + k]) + (r1[x0 + k] + r1[x1 + k]));
    }
  }
}

void ForwardScatter::widen(int level) {
  // Full-resolution pixel u samples the level at x = (u + 0.5) / 2^l - 0.5 (pixel centres), clamped.
  Level& L = levels_[level];
  const int c = channels_;
  const float scale = 1.0f / static_cast<float>(1 << level);
  for (int y = 0; y < L.height; ++y) {
    const float* in = L.data.data() + static_cast<std::size_t>(y) * L.width * c;
    float* out = L.wide.data() + static_cast<std::size_t>(y) * width_ * c;
    for (int u = 0; u < width_; ++u) {
      const float x = std::clamp((static_cast<float>(u) + 0.5f) * scale - 0.5f, 0.0f, static_cast<float>(L.width - 1));
      const int x0 = static_cast<int>(x), x1 = std::min(x0 + 1, L.width - 1);
      const float f = x - static_cast<float>(x0);
      for (int k = 0; k < c; ++k) out[u * c + k] = in[x0 * c + k] + f * (in[x1 * c + k] - in[x0 * c + k]);
    }
  }
}

void ForwardScatter::upsampledRow(int level, int v, float* out) const {
  const Level& L = levels_[level];
  const float scale = 1.0f / static_cast<float>(1 << level);
  const float y = std::clamp((static_cast<float>(v) + 0.5f) * scale - 0.5f, 0.0f, static_cast<float>(L.height - 1));
  const int y0 = static_cast<int>(y), y1 = std::min(y0 + 1, L.height - 1);
  const float f = y - static_cast<float>(y0);
  const std::size_t n = static_cast<std::size_t>(width_) * channels_;
  const float* a = L.wide.data() + static_cast<std::size_t>(y0) * n;
  const float* b = L.wide.data() + static_cast<std::size_t>(y1) * n;
  for (std::size_t i = 0; i < n; ++i) out[i] = a[i] + f * (b[i] - a[i]);
}

void ForwardScatter::apply(const float* direct, const float* distance_m, float* radiance) {
  // Each pixel's pyramid level (-1: open water), four at a time, and the levels this frame needs.
  Float4 low4 = Float4{} + static_cast<float>(kLevels), high4 = Float4{} - 1.0f;
  const std::size_t pixels = static_cast<std::size_t>(width_) * height_;
  std::size_t i = 0;
  for (; i + 4 <= pixels; i += 4) {
    const Float4 d = loadFloat4(distance_m + i);
    Float4 level = levelOf4(px_per_m_ * d);
    level = level > static_cast<float>(kLevels) ? Float4{} + static_cast<float>(kLevels) : level;
    level = d > 0.0f ? level : Float4{} - 1.0f;
    std::memcpy(level_map_.data() + i, &level, sizeof(level));
    high4 = level > high4 ? level : high4;
    low4 = (level >= 0.0f) & (level < low4) ? level : low4;
  }
  float lowest = std::min(std::min(low4[0], low4[1]), std::min(low4[2], low4[3]));
  float highest = std::max(std::max(high4[0], high4[1]), std::max(high4[2], high4[3]));
  for (; i < pixels; ++i) {
    const float level = distance_m[i] > 0.0f ? std::min(levelOf(px_per_m_ * distance_m[i]), static_cast<float>(kLevels)) : -1.0f;
    level_map_[i] = level;
    if (level >= 0.0f) lowest = std::min(lowest, level), highest = std::max(highest, level);
  }
  if (highest < 0.0f) return;  // open water only
  const int top = std::min(kLevels, static_cast<int>(std::ceil(highest)));
  reduce(direct, width_, height_, &levels_[1]);
  for (int l = 2; l <= top; ++l) reduce(levels_[l - 1].data.data(), levels_[l - 1].width, levels_[l - 1].height, &levels_[l]);
  for (int l = std::max(1, static_cast<int>(lowest)); l <= top; ++l) widen(l);
  const int c = channels_;
  const std::size_t row_n = static_cast<std::size_t>(width_) * c;
  const float last = static_cast<float>(scattered_.size() - 2);
  for (int v = 0; v < height_; ++v) {
    const float* dist = distance_m + static_cast<std::size_t>(v) * width_;
    const float* level = level_map_.data() + static_cast<std::size_t>(v) * width_;
    float row_low = static_cast<float>(kLevels), row_high = -1.0f;
    for (int u = 0; u < width_; ++u) row_high = std::max(row_high, level[u]);
    if (row_high < 0.0f) continue;
    for (int u = 0; u < width_; ++u) row_low = std::min(row_low, level[u] < 0.0f ? row_low : level[u]);
    const float* d = direct + static_cast<std::size_t>(v) * row_n;
    // The blurred row: the sum over levels of the tent weight max(0, 1 - |level - l|) times level l.
    std::fill(blurred_row_.begin(), blurred_row_.end(), 0.0f);
    for (int l = static_cast<int>(row_low); l <= std::min(kLevels, static_cast<int>(std::ceil(row_high))); ++l) {
      const float* src = d;
      if (l > 0) {
        upsampledRow(l, v, level_row_.data());
        src = level_row_.data();
      }
      const float lf = static_cast<float>(l);
      for (int u = 0; u < width_; ++u) tent_[u] = std::max(0.0f, 1.0f - std::abs(level[u] - lf));
      if (c == 1) {
        for (int u = 0; u < width_; ++u) blurred_row_[u] += tent_[u] * src[u];
      } else {
        for (int u = 0; u < width_; ++u)
          for (int k = 0; k < 3; ++k) blurred_row_[3 * u + k] += tent_[u] * src[3 * u + k];
      }
    }
    float* out = radiance + static_cast<std::size_t>(v) * row_n;
    int u = 0;
    if (c == 1) {  // four pixels at a time: 1 - exp(-b_f R) by exp4, open water masked out
      for (; u + 4 <= width_; u += 4) {
        const Float4 range = loadFloat4(dist + u);
        const Float4 scattered = 1.0f - exp4(-forward_grey_per_m_ * range);
        const Float4 change = scattered * (loadFloat4(blurred_row_.data() + u) - loadFloat4(d + u));
        const Float4 sum = loadFloat4(out + u) + (loadFloat4(level + u) >= 0.0f ? change : Float4{});
        std::memcpy(out + u, &sum, sizeof(sum));
      }
    }
    for (; u < width_; ++u) {
      if (level[u] < 0.0f) continue;
      // 1 - exp(-b_f R) per channel, from the table.
      const float x = std::min(dist[u] * (1.0f / kStep_m), last);
      const int i = static_cast<int>(x);
      const Float4 scattered = scattered_[i] + (x - static_cast<float>(i)) * (scattered_[i + 1] - scattered_[i]);
      for (int k = 0; k < c; ++k) out[u * c + k] += scattered[k] * (blurred_row_[u * c + k] - d[u * c + k]);
    }
  }
}

}  // namespace deepnav::sim
