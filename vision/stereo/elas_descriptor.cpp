#include "vision/stereo/elas_descriptor.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

alignas(16) constexpr std::uint8_t kFlat[16] = {128, 128, 128, 128, 128, 128, 128, 128,
                                                128, 128, 128, 128, 128, 128, 128, 128};

std::uint8_t saturateOffset(int scaled_response) {
  return static_cast<std::uint8_t>(std::clamp(scaled_response + 128, 0, 255));
}

}  // namespace

int descriptorTexture(const std::uint8_t* descriptor) { return sad16(descriptor, kFlat); }

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
    for (int u = 0; u < w; ++u) {
      const int l = std::max(u - 1, 0);
      const int r = std::min(u + 1, w - 1);
      const int dx = (up[r] - up[l]) + 2 * (mid[r] - mid[l]) + (down[r] - down[l]);
      const int dy = (down[l] - up[l]) + 2 * (down[u] - up[u]) + (down[r] - up[r]);
      gx[u] = static_cast<std::int16_t>(dx);
      gy[u] = static_cast<std::int16_t>(dy);
      ++(*histogram)[std::abs(dx)];
    }
  }
}

// Fixed point: gain in 1/256 steps, responses rounded towards minus infinity.
void ElasDescriptorImage::computeDescriptors(float gain) {
  const int gain_q8 = static_cast<int>(std::lround(gain * 256.0f));
  for (std::size_t i = 0; i < raw_gx_.size(); ++i) {
    gx_[i] = saturateOffset((raw_gx_[i] * gain_q8) >> 8);
    gy_[i] = saturateOffset((raw_gy_[i] * gain_q8) >> 8);
  }
  for (int v = 0; v < height_px_; ++v) gatherRow(v);
}

// Taps outside the image are clamped to the border (the border pixels keep a full descriptor);
// interior pixels, the vast majority, take the taps at fixed offsets without clamping.
void ElasDescriptorImage::gatherRow(int v) {
  constexpr int kReachU = 4;
  constexpr int kReachV = 2;
  const int w = width_px_;
  const int h = height_px_;
  std::uint8_t* out = descriptors_.data() + static_cast<std::size_t>(v) * w * kBytes;
  const bool interior_row = v >= kReachV && v < h - kReachV;
  std::ptrdiff_t gx_offset[11], gy_offset[5];
  for (int k = 0; k < 11; ++k)
    gx_offset[k] = static_cast<std::ptrdiff_t>(kGxTaps[k].dv) * w + kGxTaps[k].du;
  for (int k = 0; k < 5; ++k)
    gy_offset[k] = static_cast<std::ptrdiff_t>(kGyTaps[k].dv) * w + kGyTaps[k].du;
  for (int u = 0; u < w; ++u, out += kBytes) {
    const std::size_t centre = static_cast<std::size_t>(v) * w + u;
    if (interior_row && u >= kReachU && u < w - kReachU) {
      for (int k = 0; k < 11; ++k) out[k] = gx_[centre + gx_offset[k]];
      for (int k = 0; k < 5; ++k) out[11 + k] = gy_[centre + gy_offset[k]];
      continue;
    }
    int k = 0;
    for (const Tap& t : kGxTaps) {
      const int uu = std::clamp(u + t.du, 0, w - 1);
      const int vv = std::clamp(v + t.dv, 0, h - 1);
      out[k++] = gx_[static_cast<std::size_t>(vv) * w + uu];
    }
    for (const Tap& t : kGyTaps) {
      const int uu = std::clamp(u + t.du, 0, w - 1);
      const int vv = std::clamp(v + t.dv, 0, h - 1);
      out[k++] = gy_[static_cast<std::size_t>(vv) * w + uu];
    }
  }
}

}  // namespace deepnav
