#include "vision/orbvo/steered_brief.h"

#include <cmath>
#include <numbers>
#include <opencv2/core/hal/intrin.hpp>

namespace deepnav {
namespace {

// splitmix64 (Steele, Lea & Flood 2014): a tiny deterministic generator, the same on every
// platform.
std::uint64_t nextRandom(std::uint64_t* state) {
  std::uint64_t z = (*state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

double uniform01(std::uint64_t* state) {
  return (static_cast<double>(nextRandom(state) >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

// One N(0, sigma^2) sample inside the disc of radius r (Box-Muller, rejection outside the disc).
void gaussianPointInDisc(std::uint64_t* state, double sigma, double r, double* x, double* y) {
  for (;;) {
    const double rho = sigma * std::sqrt(-2.0 * std::log(uniform01(state)));
    const double phi = 2.0 * std::numbers::pi * uniform01(state);
    *x = rho * std::cos(phi);
    *y = rho * std::sin(phi);
    if ((*x) * (*x) + (*y) * (*y) <= r * r) return;
  }
}

// The rotation bin of angle_rad (kAngleBins bins, nearest).
int angleBin(float angle_rad) {
  constexpr double kBinRad = 2.0 * std::numbers::pi / SteeredBrief::kAngleBins;
  int bin = static_cast<int>(std::lround(angle_rad / kBinRad)) % SteeredBrief::kAngleBins;
  if (bin < 0) bin += SteeredBrief::kAngleBins;
  return bin;
}

}  // namespace

SteeredBrief::SteeredBrief() {
  constexpr double kSigmaPx = 31.0 / 5.0;
  std::uint64_t state = 0x0DE5EA0B5E5ull;
  std::array<double, 4 * kBits> base{};
  for (int i = 0; i < kBits; ++i) {
    gaussianPointInDisc(&state, kSigmaPx, kPairRadiusPx, &base[4 * i], &base[4 * i + 1]);
    gaussianPointInDisc(&state, kSigmaPx, kPairRadiusPx, &base[4 * i + 2], &base[4 * i + 3]);
  }
  for (int b = 0; b < kAngleBins; ++b) {
    const double theta = 2.0 * std::numbers::pi * b / kAngleBins;
    const double c = std::cos(theta);
    const double s = std::sin(theta);
    for (int k = 0; k < 2 * kBits; ++k) {
      const double x = base[2 * k];
      const double y = base[2 * k + 1];
      pairs_[b][2 * k] = static_cast<std::int8_t>(std::lround(c * x - s * y));
      pairs_[b][2 * k + 1] = static_cast<std::int8_t>(std::lround(s * x + c * y));
    }
  }
  for (int dy = 0; dy <= kOrientationRadiusPx; ++dy) {
    disc_half_width_[dy] = static_cast<int>(std::floor(
        std::sqrt(static_cast<double>(kOrientationRadiusPx * kOrientationRadiusPx - dy * dy))));
    for (int j = 0; j < 32; ++j) {
      const int u = j - kOrientationRadiusPx;
      const bool inside = std::abs(u) <= disc_half_width_[dy];
      u_weight_[dy][j] = static_cast<std::int16_t>(inside ? u : 0);
      dy_weight_[dy][j] = static_cast<std::int16_t>(inside ? dy : 0);
    }
  }
}

float SteeredBrief::orientationRad(const cv::Mat& image, int x, int y) const {
#if CV_SIMD128
  // 32 columns from x - 15 (x + 16 lies inside the image: x <= cols - kBorderPx - 1), widened to
  // 16 bits; products and pair sums fit 32 bits (|u| <= 15, pixel sums <= 510).
  const int step = static_cast<int>(image.step1());
  const std::uint8_t* first = image.ptr<std::uint8_t>(y) + x - kOrientationRadiusPx;
  const auto widen = [](const std::uint8_t* p, cv::v_int16x8 out[4]) {
    cv::v_uint16x8 a, b, c, d;
    cv::v_expand(cv::v_load(p), a, b);
    cv::v_expand(cv::v_load(p + 16), c, d);
    out[0] = cv::v_reinterpret_as_s16(a);
    out[1] = cv::v_reinterpret_as_s16(b);
    out[2] = cv::v_reinterpret_as_s16(c);
    out[3] = cv::v_reinterpret_as_s16(d);
  };
  cv::v_int32x4 m10 = cv::v_setzero_s32();
  cv::v_int32x4 m01 = cv::v_setzero_s32();
  cv::v_int16x8 below[4], above[4];
  widen(first, below);
  for (int k = 0; k < 4; ++k) m10 += cv::v_dotprod(below[k], cv::v_load(&u_weight_[0][8 * k]));
  for (int dy = 1; dy <= kOrientationRadiusPx; ++dy) {
    widen(first + dy * step, below);
    widen(first - dy * step, above);
    for (int k = 0; k < 4; ++k) {
      m10 += cv::v_dotprod(below[k] + above[k], cv::v_load(&u_weight_[dy][8 * k]));
      m01 += cv::v_dotprod(below[k] - above[k], cv::v_load(&dy_weight_[dy][8 * k]));
    }
  }
  return static_cast<float>(std::atan2(static_cast<double>(cv::v_reduce_sum(m01)),
                                       static_cast<double>(cv::v_reduce_sum(m10))));
#else
  return orientationRadScalar(image, x, y);
#endif
}

void SteeredBrief::fillOffsets(int step, Offsets* out) const {
  out->step = step;
  for (int b = 0; b < kAngleBins; ++b) {
    for (int k = 0; k < 2 * kBits; ++k) {
      out->offset[b][k] = pairs_[b][2 * k + 1] * step + pairs_[b][2 * k];
    }
  }
}

void SteeredBrief::describe(const cv::Mat& smoothed, const Offsets& offsets, int x, int y,
                            float angle_rad, OrbDescriptor* out) const {
  const int* offset = offsets.offset[angleBin(angle_rad)].data();
  const std::uint8_t* centre = smoothed.ptr<std::uint8_t>(y) + x;
  for (int word = 0; word < 4; ++word) {
    std::uint64_t bits = 0;
    // unrolled, the shifts are constants: 8 instructions per bit instead of 11
#pragma GCC unroll 64
    for (int i = 0; i < 64; ++i) {
      bits |= static_cast<std::uint64_t>(centre[offset[2 * i]] < centre[offset[2 * i + 1]]) << i;
    }
    offset += 128;
    (*out)[word] = bits;
  }
}

float SteeredBrief::orientationRadScalar(const cv::Mat& image, int x, int y) const {
  const int step = static_cast<int>(image.step1());
  const std::uint8_t* centre = image.ptr<std::uint8_t>(y) + x;
  int m10 = 0;
  int m01 = 0;
  for (int u = -kOrientationRadiusPx; u <= kOrientationRadiusPx; ++u) m10 += u * centre[u];
  for (int dy = 1; dy <= kOrientationRadiusPx; ++dy) {
    const int hw = disc_half_width_[dy];
    for (int u = -hw; u <= hw; ++u) {
      const int below = centre[dy * step + u];
      const int above = centre[-dy * step + u];
      m10 += u * (below + above);
      m01 += dy * (below - above);
    }
  }
  return static_cast<float>(std::atan2(static_cast<double>(m01), static_cast<double>(m10)));
}

void SteeredBrief::describe(const cv::Mat& smoothed, int x, int y, float angle_rad,
                            OrbDescriptor* out) const {
  const std::int8_t* pair = pairs_[angleBin(angle_rad)].data();
  const int step = static_cast<int>(smoothed.step1());
  const std::uint8_t* centre = smoothed.ptr<std::uint8_t>(y) + x;
  for (int word = 0; word < 4; ++word) {
    std::uint64_t bits = 0;
    for (int i = 0; i < 64; ++i, pair += 4) {
      const int p = centre[pair[1] * step + pair[0]];
      const int q = centre[pair[3] * step + pair[2]];
      bits |= static_cast<std::uint64_t>(p < q) << i;
    }
    (*out)[word] = bits;
  }
}

}  // namespace deepnav
