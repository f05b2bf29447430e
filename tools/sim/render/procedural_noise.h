#pragma once
#include <cstdint>

#include <opencv2/core.hpp>

namespace deepnav::sim {

// Hash-based value noise for the procedural textures and the seabed relief: integer hashing of the
// lattice (no std distributions), so a seed gives the same lattice on every platform.

std::uint32_t hashU32(std::uint32_t x);
std::uint32_t hashU32(std::uint32_t a, std::uint32_t b, std::uint32_t c);

// Lattice value in [-1, 1] of integer point (ix, iy).
float latticeValue(int ix, int iy, std::uint32_t seed);

// Value noise as a whole image at once (far faster than per-texel evaluation): lattice values
// every cell_x by cell_y texels, interpolated bicubically (cv::resize), in about [-1, 1], CV_32F.
// wrap: the image tiles (width and height must be multiples of the cells).
cv::Mat valueNoiseImage(int width, int height, float cell_x, float cell_y, std::uint32_t seed, bool wrap = false);
// Fractal sum of `octaves` such images (cells halved, amplitude x gain each), divided by the sum of the
// amplitudes.
cv::Mat fractalNoiseImage(int width, int height, float cell, int octaves, float gain, std::uint32_t seed,
                          bool wrap = false);

}  // namespace deepnav::sim
