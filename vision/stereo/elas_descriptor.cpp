#include "vision/stereo/elas_descriptor.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <opencv2/core/hal/intrin.hpp>

#include "vision/stereo/sad16.h"

namespace deepnav {
namespace {

// Sample pattern in the 9x9 window {du, dv}: gx (the response that changes with disparity) on a
// cross and ring, gy on a small cross to disambiguate along edges (aperture problem).
struct Tap {
  int du, dv;
};
constexpr Tap kGxTaps[11] = {{-4, 0}, {-2, 0}, {0, 0},  {2, 0}, {4, 0}, {-2, -2},
                             {0, -2}, {2, -2}, {-2, 2}, {0, 2}, {2, 2}};
constexpr Tap kGyTaps[5] = {{0, 0}, {-2, 0}, {2, 0}, {0, -2}, {0, 2}};

std::uint8_t saturateOffset(int scaled_response) {
  return static_cast<std::uint8_t>(std::clamp(scaled_response + 128, 0, 255));
}

// Sobel responses of columns [1, returned end) of one row, 8 at a time in 16-bit lanes (|response| <=
// 4 * 255 fits). The caller does the border columns and the tail.
int sobelRowInterior(const std::uint8_t* up, const std::uint8_t* mid, const std::uint8_t* down, int w,
                     std::int16_t* gx, std::int16_t* gy) {
  int u = 1;
#if CV_SIMD128
  for (; u + 8 <= w - 1; u += 8) {
    const auto load = [](const std::uint8_t* p) { return cv::v_reinterpret_as_s16(cv::v_load_expand(p)); };
    const cv::v_int16x8 up_l = load(up + u - 1), up_c = load(up + u), up_r = load(up + u + 1);
    const cv::v_int16x8 mid_l = load(mid + u - 1), mid_r = load(mid + u + 1);
    const cv::v_int16x8 down_l = load(down + u - 1), down_c = load(down + u), down_r = load(down + u + 1);
    const cv::v_int16x8 dmid = mid_r - mid_l;
    const cv::v_int16x8 dx = (up_r - up_l) + (dmid + dmid) + (down_r - down_l);
    const cv::v_int16x8 dcentre = down_c - up_c;
    const cv::v_int16x8 dy = (down_l - up_l) + (dcentre + dcentre) + (down_r - up_r);
    cv::v_store(gx + u, dx);
    cv::v_store(gy + u, dy);
  }
#endif
  return u;
}

// saturateOffset((raw * gain_q8) >> 8) of the first returned count of n responses, 16 at a time: 32-bit
// products (|raw| <= 1020), arithmetic shift, offset added in 16 bits (|x| <= 4080 * gain / 4 + 128
// for gain <= 4; the 32 -> 16 bit pack saturates larger gains, whose bytes saturate anyway), then
// packed to bytes with unsigned saturation: the same bytes as the scalar formula.
std::size_t scaleResponses(const std::int16_t* raw_gx, const std::int16_t* raw_gy, std::size_t n, int gain_q8,
                           std::uint8_t* gx, std::uint8_t* gy) {
  std::size_t i = 0;
#if CV_SIMD128
  const cv::v_int32x4 gain = cv::v_setall_s32(gain_q8);
  const cv::v_int16x8 offset = cv::v_setall_s16(128);
  const auto scale8 = [&](const std::int16_t* p) {
    cv::v_int32x4 lo, hi;
    cv::v_expand(cv::v_load(p), lo, hi);
    return cv::v_pack((lo * gain) >> 8, (hi * gain) >> 8) + offset;
  };
  for (; i + 16 <= n; i += 16) {
    cv::v_store(gx + i, cv::v_pack_u(scale8(raw_gx + i), scale8(raw_gx + i + 8)));
    cv::v_store(gy + i, cv::v_pack_u(scale8(raw_gy + i), scale8(raw_gy + i + 8)));
  }
#endif
  return i;
}

// out[16 j + k] = taps[k][u + j] for j, k in [0, 16): four rounds of interleaving transpose the 16x16
// block of bytes (rows: taps, columns: pixels) into 16 descriptors.
void gather16(const std::uint8_t* const* taps, int u, std::uint8_t* out) {
#if CV_SIMD128
  cv::v_uint8x16 row[16];
  for (int k = 0; k < 16; ++k) row[k] = cv::v_load(taps[k] + u);
  // a[2m + h], 16-bit lane i: taps 2m, 2m+1 of pixel 8h + i
  cv::v_uint8x16 a[16];
  for (int m = 0; m < 8; ++m) cv::v_zip(row[2 * m], row[2 * m + 1], a[2 * m], a[2 * m + 1]);
  // b[4q + P], 32-bit lane i: taps 4q .. 4q+3 of pixel 4P + i
  cv::v_uint16x8 b[16];
  for (int q = 0; q < 4; ++q) {
    for (int h = 0; h < 2; ++h) {
      cv::v_zip(cv::v_reinterpret_as_u16(a[4 * q + h]), cv::v_reinterpret_as_u16(a[4 * q + 2 + h]),
                b[4 * q + 2 * h], b[4 * q + 2 * h + 1]);
    }
  }
  // c[8r + Q], 64-bit lane i: taps 8r .. 8r+7 of pixel 2Q + i
  cv::v_uint32x4 c[16];
  for (int r = 0; r < 2; ++r) {
    for (int p = 0; p < 4; ++p) {
      cv::v_zip(cv::v_reinterpret_as_u32(b[8 * r + p]), cv::v_reinterpret_as_u32(b[8 * r + 4 + p]),
                c[8 * r + 2 * p], c[8 * r + 2 * p + 1]);
    }
  }
  for (int q = 0; q < 8; ++q) {
    cv::v_uint32x4 even, odd;
    cv::v_recombine(c[q], c[8 + q], even, odd);
    cv::v_store(out + 32 * q, cv::v_reinterpret_as_u8(even));
    cv::v_store(out + 32 * q + 16, cv::v_reinterpret_as_u8(odd));
  }
#else
  for (int j = 0; j < 16; ++j) {
    for (int k = 0; k < 16; ++k) out[16 * j + k] = taps[k][u + j];
  }
#endif
}

}  // namespace

float descriptorGain(const SobelHistogram& histogram, float target, float max_gain,
                     float fixed_gain) {
  if (fixed_gain > 0.0f) return fixed_gain;
  std::uint64_t total = 0;
  for (std::uint32_t c : histogram) total += c;
  const std::uint64_t rank = total * 9 / 10;
  std::uint64_t seen = 0;
  int p90 = 1;
  for (int i = 0; i < static_cast<int>(histogram.size()); ++i) {
    seen += histogram[i];
    if (seen > rank) {
      p90 = std::max(i, 1);
      break;
    }
  }
  return std::min(max_gain, target / static_cast<float>(p90));
}

bool ElasDescriptorImage::allocate(int width_px, int height_px) {
  if (width_px < 16 || height_px < 16) return false;
  width_px_ = width_px;
  height_px_ = height_px;
  const std::size_t pixels = static_cast<std::size_t>(width_px) * height_px;
  raw_gx_.assign(pixels, 0);
  raw_gy_.assign(pixels, 0);
  gx_.assign(pixels, 128);
  gy_.assign(pixels, 128);
  descriptors_.assign(pixels * kBytes, 128);
  return true;
}

// 3x3 Sobel with replicated borders: gx = [1 2 1]^T [-1 0 1], gy = [-1 0 1]^T [1 2 1].
void ElasDescriptorImage::computeGradients(const cv::Mat& grey, SobelHistogram* histogram) {
  const int w = width_px_;
  for (int v = 0; v < height_px_; ++v) {
    const std::uint8_t* up = grey.ptr<std::uint8_t>(std::max(v - 1, 0));
    const std::uint8_t* mid = grey.ptr<std::uint8_t>(v);
    const std::uint8_t* down = grey.ptr<std::uint8_t>(std::min(v + 1, height_px_ - 1));
    std::int16_t* gx = raw_gx_.data() + static_cast<std::size_t>(v) * w;
    std::int16_t* gy = raw_gy_.data() + static_cast<std::size_t>(v) * w;
    const int u_simd = sobelRowInterior(up, mid, down, w, gx, gy);
    for (int u = 0; u < w; ++u) {
      if (u >= 1 && u < u_simd) u = u_simd;  // the interior was done with vectors
      if (u >= w) break;
      const int l = std::max(u - 1, 0);
      const int r = std::min(u + 1, w - 1);
      gx[u] = static_cast<std::int16_t>((up[r] - up[l]) + 2 * (mid[r] - mid[l]) + (down[r] - down[l]));
      gy[u] = static_cast<std::int16_t>((down[l] - up[l]) + 2 * (down[u] - up[u]) + (down[r] - up[r]));
    }
    for (int u = 0; u < w; ++u) ++(*histogram)[std::abs(gx[u])];
  }
}

// Fixed point: gain in 1/256 steps, responses rounded towards minus infinity.
void ElasDescriptorImage::computeDescriptors(float gain) {
  const int gain_q8 = static_cast<int>(std::lround(gain * 256.0f));
  const std::size_t n = raw_gx_.size();
  const std::size_t n_simd = scaleResponses(raw_gx_.data(), raw_gy_.data(), n, gain_q8, gx_.data(), gy_.data());
  for (std::size_t i = n_simd; i < n; ++i) {
    gx_[i] = saturateOffset((raw_gx_[i] * gain_q8) >> 8);
    gy_[i] = saturateOffset((raw_gy_[i] * gain_q8) >> 8);
  }
  for (int v = 0; v < height_px_; ++v) gatherRow(v);
}

// Taps outside the image are clamped to the border (the border pixels keep a full descriptor);
// interior pixels, the vast majority, take the taps at fixed offsets without clamping, 16 pixels at
// a time: the 16 tap rows (16 consecutive pixels each) transposed into 16 descriptors.
void ElasDescriptorImage::gatherRow(int v) {
  constexpr int kReachU = 4;
  constexpr int kReachV = 2;
  const int w = width_px_;
  const int h = height_px_;
  std::uint8_t* row_out = descriptors_.data() + static_cast<std::size_t>(v) * w * kBytes;
  const bool interior_row = v >= kReachV && v < h - kReachV;
  if (interior_row) {
    // every tap of u in [kReachU, w - kReachU) lies inside the image
    const std::uint8_t* taps[kBytes];
    for (int k = 0; k < 11; ++k) {
      taps[k] = gx_.data() + static_cast<std::ptrdiff_t>(v + kGxTaps[k].dv) * w + kGxTaps[k].du;
    }
    for (int k = 0; k < 5; ++k) {
      taps[11 + k] = gy_.data() + static_cast<std::ptrdiff_t>(v + kGyTaps[k].dv) * w + kGyTaps[k].du;
    }
    int u = kReachU;
    for (; u + 16 <= w - kReachU; u += 16) gather16(taps, u, row_out + static_cast<std::size_t>(u) * kBytes);
    for (; u < w - kReachU; ++u) {
      for (int k = 0; k < kBytes; ++k) row_out[static_cast<std::size_t>(u) * kBytes + k] = taps[k][u];
    }
  }
  for (int u = 0; u < w; ++u) {
    if (interior_row && u == kReachU) u = w - kReachU;  // the interior is done
    std::uint8_t* out = row_out + static_cast<std::size_t>(u) * kBytes;
    int k = 0;
    for (const Tap& t : kGxTaps) {
      const int tu = std::clamp(u + t.du, 0, w - 1);
      const int tv = std::clamp(v + t.dv, 0, h - 1);
      out[k++] = gx_[static_cast<std::size_t>(tv) * w + tu];
    }
    for (const Tap& t : kGyTaps) {
      const int tu = std::clamp(u + t.du, 0, w - 1);
      const int tv = std::clamp(v + t.dv, 0, h - 1);
      out[k++] = gy_[static_cast<std::size_t>(tv) * w + tu];
    }
  }
}

}  // namespace deepnav
