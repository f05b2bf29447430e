#include "tools/sim/render/procedural_noise.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace deepnav::sim {

std::uint32_t hashU32(std::uint32_t x) {
  // "lowbias32" integer finaliser (Chris Wellons): good avalanche, two multiplies.
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

std::uint32_t hashU32(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  return hashU32(a ^ hashU32(b ^ hashU32(c + 0x9e3779b9U)));
}

float latticeValue(int ix, int iy, std::uint32_t seed) {
  const std::uint32_t h = hashU32(static_cast<std::uint32_t>(ix), static_cast<std::uint32_t>(iy), seed);
  return static_cast<float>(h >> 8) * (2.0f / 16777216.0f) - 1.0f;
}

cv::Mat valueNoiseImage(int width, int height, float cell_x, float cell_y, std::uint32_t seed, bool wrap) {
  // Lattice with a 2-cell margin each side so the bicubic kernel never reads past it; wrapped lattices
  // repeat their values in the margin, so the cropped image tiles.
  constexpr int kMargin = 2;
  const int nx = std::max(1, static_cast<int>(std::ceil(width / cell_x))) + (wrap ? 0 : 1);
  const int ny = std::max(1, static_cast<int>(std::ceil(height / cell_y))) + (wrap ? 0 : 1);
  cv::Mat lattice(ny + 2 * kMargin, nx + 2 * kMargin, CV_32F);
  for (int j = 0; j < lattice.rows; ++j) {
    float* row = lattice.ptr<float>(j);
    const int y = wrap ? ((j - kMargin) % ny + ny) % ny : j;
    for (int i = 0; i < lattice.cols; ++i) {
      const int x = wrap ? ((i - kMargin) % nx + nx) % nx : i;
      row[i] = latticeValue(x, y, seed);
    }
  }
  // Output texel (x + 0.5) maps to lattice coordinate (x + 0.5) / cell + margin (cv::resize's centre
  // convention), so lattice node k sits at texel k * cell - 0.5.
  cv::Mat big;
  const int big_w = static_cast<int>(std::lround(lattice.cols * cell_x));
  const int big_h = static_cast<int>(std::lround(lattice.rows * cell_y));
  cv::resize(lattice, big, cv::Size(big_w, big_h), 0.0, 0.0, cv::INTER_CUBIC);
  const int x0 = static_cast<int>(std::lround(kMargin * cell_x)), y0 = static_cast<int>(std::lround(kMargin * cell_y));
  return big(cv::Rect(x0, y0, width, height)).clone();
}

cv::Mat fractalNoiseImage(int width, int height, float cell, int octaves, float gain, std::uint32_t seed, bool wrap) {
  cv::Mat sum(height, width, CV_32F, cv::Scalar(0.0f));
  float norm = 0.0f, amplitude = 1.0f;
  for (int k = 0; k < octaves && cell >= 1.0f; ++k) {
    sum += amplitude * valueNoiseImage(width, height, cell, cell, seed + 7919U * static_cast<std::uint32_t>(k), wrap);
    norm += amplitude;
    amplitude *= gain;
    cell *= 0.5f;
  }
  if (norm > 0.0f) sum *= 1.0f / norm;
  return sum;
}

}  // namespace deepnav::sim
