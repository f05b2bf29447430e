#include "vision/stereo/disparity_edge_refiner.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace deepnav {
namespace {

constexpr int kMaxColourDiff = 3 * 255;
constexpr std::uint16_t kNoBin = 0xFFFF;
// Invalid pixels take part in the window loops without a branch: their guide key points the weight
// lookup at zeros past the weights (grey: key 512 instead of the grey level, LUT index 255 - centre +
// key > 510; colour: 1024 added to the colour distance <= 765) and their bin is a spare one past the
// disparities. Adding the weight 0 leaves every sum exactly as it was (x + 0.0f == x for x >= 0), and
// the spare bin, always 0, is never the median.
constexpr std::uint16_t kInvalidGrey = 512;
constexpr std::uint16_t kInvalidColour = 1024;

// Running-count dilation of one line of n flags spaced by stride.
void dilateLine(const std::uint8_t* in, std::uint8_t* out, int n, std::ptrdiff_t stride, int r) {
  int count = 0;
  for (int i = 0; i < std::min(r, n); ++i) count += in[i * stride];
  for (int i = 0; i < n; ++i) {
    if (i + r < n) count += in[(i + r) * stride];
    if (i - r - 1 >= 0) count -= in[(i - r - 1) * stride];
    out[i * stride] = count > 0 ? 1 : 0;
  }
}

// Lattice step of the window samples: 2 px unless the band is so large that the budget of
// samples per image pixel would be exceeded; then 4, then 8.
int chooseStride(std::size_t band_px, std::size_t image_px, int radius_px, float budget) {
  for (int stride : {2, 4}) {
    const double per_axis = 2.0 * (radius_px / stride) + 1.0;
    const double samples = static_cast<double>(band_px) * per_axis * per_axis;
    if (samples <= budget * static_cast<double>(image_px)) return stride;
  }
  return 8;
}

// First lattice offset in [-reach, reach] (step stride) that keeps centre + offset >= 0.
int firstOffset(int centre, int reach, int stride) {
  const int offset = -reach;
  if (centre + offset >= 0) return offset;
  return offset + (-(centre + offset) + stride - 1) / stride * stride;
}

}  // namespace


bool DisparityEdgeRefiner::allocate(int width_px, int height_px, int num_disparities) {
  if (width_px < 1 || height_px < 1 || num_disparities < 1 || num_disparities >= kNoBin) {
    return false;
  }
  width_px_ = width_px;
  height_px_ = height_px;
  bins_ = num_disparities + 1;
  const std::size_t pixels = static_cast<std::size_t>(width_px) * height_px;
  jump_.assign(pixels, 0);
  band_.assign(pixels, 0);
  rows_.assign(pixels, 0);
  column_count_.assign(static_cast<std::size_t>(width_px), 0);
  bin_.assign(pixels, static_cast<std::uint16_t>(bins_));
  guide_key_.assign(pixels, 0);
  weight_lut_.assign(kInvalidColour + kMaxColourDiff + 1, 0.0f);
  weight_by_grey_diff_.assign(255 + kInvalidGrey + 1, 0.0f);
  hist_w_.assign(static_cast<std::size_t>(bins_) + 1, 0.0f);
  hist_wd_.assign(static_cast<std::size_t>(bins_) + 1, 0.0f);
  source_px_.create(height_px, width_px, CV_32F);
  return true;
}

// Also records each pixel's integer disparity bin for the medians.
void DisparityEdgeRefiner::markJumps(const cv::Mat& d, float jump_px) {
  const int w = width_px_;
  for (int v = 0; v < height_px_; ++v) {
    const float* row = d.ptr<float>(v);
    const float* down = d.ptr<float>(std::min(v + 1, height_px_ - 1));
    std::uint8_t* jump = jump_.data() + static_cast<std::size_t>(v) * w;
    std::uint16_t* bin = bin_.data() + static_cast<std::size_t>(v) * w;
    for (int u = 0; u < w; ++u) {
      const float a = row[u];
      const float right = row[std::min(u + 1, w - 1)];
      const bool is_jump = a >= 0.0f && ((right >= 0.0f && std::fabs(right - a) > jump_px) ||
                                         (down[u] >= 0.0f && std::fabs(down[u] - a) > jump_px));
      jump[u] = is_jump ? 1 : 0;
      bin[u] = a >= 0.0f
                   ? static_cast<std::uint16_t>(std::min(bins_ - 1, static_cast<int>(a + 0.5f)))
                   : static_cast<std::uint16_t>(bins_);
    }
  }
}

template <int kChannels>
void DisparityEdgeRefiner::markGuideKeys(const cv::Mat& guide) {
  const int spare_bin = bins_;
  for (int v = 0; v < height_px_; ++v) {
    const std::uint8_t* g = guide.ptr<std::uint8_t>(v);
    const std::uint16_t* bin = bin_.data() + static_cast<std::size_t>(v) * width_px_;
    std::uint16_t* key = guide_key_.data() + static_cast<std::size_t>(v) * width_px_;
    for (int u = 0; u < width_px_; ++u) {
      const bool valid = bin[u] != spare_bin;
      if constexpr (kChannels == 1) {
        key[u] = valid ? g[u] : kInvalidGrey;
      } else {
        key[u] = valid ? 0 : kInvalidColour;
      }
    }
  }
}

void DisparityEdgeRefiner::dilateJumps(int r) {
  const int w = width_px_;
  for (int v = 0; v < height_px_; ++v) {
    const std::size_t offset = static_cast<std::size_t>(v) * w;
    dilateLine(jump_.data() + offset, rows_.data() + offset, w, 1, r);
  }
  dilateColumns(rows_.data(), band_.data(), r);
}

// dilateLine down every column at once: one running count per column, walked row by row (the
// column-by-column walk strode through memory a row apart).
void DisparityEdgeRefiner::dilateColumns(const std::uint8_t* in, std::uint8_t* out, int r) {
  const int w = width_px_;
  const int h = height_px_;
  std::int32_t* count = column_count_.data();
  std::fill(column_count_.begin(), column_count_.end(), 0);
  const auto row = [&](const std::uint8_t* image, int v) { return image + static_cast<std::size_t>(v) * w; };
  for (int v = 0; v < std::min(r, h); ++v) {
    const std::uint8_t* add = row(in, v);
    for (int u = 0; u < w; ++u) count[u] += add[u];
  }
  for (int v = 0; v < h; ++v) {
    if (v + r < h) {
      const std::uint8_t* add = row(in, v + r);
      for (int u = 0; u < w; ++u) count[u] += add[u];
    }
    if (v - r - 1 >= 0) {
      const std::uint8_t* sub = row(in, v - r - 1);
      for (int u = 0; u < w; ++u) count[u] -= sub[u];
    }
    std::uint8_t* o = out + static_cast<std::size_t>(v) * w;
    for (int u = 0; u < w; ++u) o[u] = count[u] > 0 ? 1 : 0;
  }
}

// The histograms are zero between calls: only the bins a window touched are scanned and cleared
// (the other bins hold zeros, which change neither the running sum nor the median), in the same
// order and with the same float operations as a scan of every bin.
template <int kChannels>
float DisparityEdgeRefiner::weightedMedian(const cv::Mat& guide, int u, int v, int reach) {
  const std::uint8_t* centre = guide.ptr<std::uint8_t>(v) + u * kChannels;
  const int stride = stride_px_;
  const int dv_first = firstOffset(v, reach, stride);
  const int du_first = firstOffset(u, reach, stride);
  const int v_last = std::min(v + reach, height_px_ - 1);
  const int u_last = std::min(u + reach, width_px_ - 1);
  float* hist_w = hist_w_.data();
  float* hist_wd = hist_wd_.data();
  // grey: the weight straight from the signed difference (no abs, no scale: the grey LUT holds
  // weight_lut_[3 |g|], the colour scale); colour: from the l1 sum
  const float* lut_grey = weight_by_grey_diff_.data() + 255 - centre[0];
  const float* lut = weight_lut_.data();
  int bin_lo = bins_, bin_hi = -1;
  float total = 0.0f;
  for (int v2 = v + dv_first; v2 <= v_last; v2 += stride) {
    const std::uint16_t* bin_row = bin_.data() + static_cast<std::size_t>(v2) * width_px_;
    const std::uint16_t* key_row = guide_key_.data() + static_cast<std::size_t>(v2) * width_px_;
    const float* d_row = source_px_.ptr<float>(v2);
    const std::uint8_t* g_row = guide.ptr<std::uint8_t>(v2);
    for (int u2 = u + du_first; u2 <= u_last; u2 += stride) {
      const int bin = bin_row[u2];  // the spare bin, with weight 0, when invalid
      float wq;
      if constexpr (kChannels == 1) {
        wq = lut_grey[key_row[u2]];
      } else {
        const std::uint8_t* q = g_row + u2 * kChannels;
        int diff = key_row[u2];
        for (int c = 0; c < kChannels; ++c) diff += std::abs(q[c] - centre[c]);
        wq = lut[diff];
      }
      hist_w[bin] += wq;
      hist_wd[bin] += wq * d_row[u2];
      total += wq;
      bin_lo = std::min(bin_lo, bin);
      bin_hi = std::max(bin_hi, bin);
    }
  }
  // the median bin, reported as the weighted mean of its members (keeps sub-pixel values)
  float result = source_px_.at<float>(v, u);
  float acc = 0.0f;
  const float half = 0.5f * total;
  for (int b = bin_lo; b <= bin_hi; ++b) {
    acc += hist_w[b];
    if (hist_w[b] > 0.0f && acc >= half) {
      result = hist_wd[b] / hist_w[b];
      break;
    }
  }
  if (bin_hi >= bin_lo) {
    std::fill(hist_w + bin_lo, hist_w + bin_hi + 1, 0.0f);
    std::fill(hist_wd + bin_lo, hist_wd + bin_hi + 1, 0.0f);
  }
  return result;
}

template <int kChannels>
void DisparityEdgeRefiner::refineBand(const cv::Mat& guide, int radius_px, cv::Mat* disparity_px) {
  const int reach = radius_px - radius_px % stride_px_;  // lattice points within the radius
  for (int v = 0; v < height_px_; ++v) {
    float* out = disparity_px->ptr<float>(v);
    const std::uint8_t* band = band_.data() + static_cast<std::size_t>(v) * width_px_;
    for (int u = 0; u < width_px_; ++u) {
      if (band[u] && out[u] >= 0.0f) out[u] = weightedMedian<kChannels>(guide, u, v, reach);
    }
  }
}

void DisparityEdgeRefiner::apply(const cv::Mat& guide, const EdgeRefineParams& params,
                                 cv::Mat* disparity_px) {
  if (params.band_px < 1 || params.radius_px < 1 || params.sigma <= 0.0f) return;
  if (params.sigma != lut_sigma_) {
    for (int i = 0; i <= kMaxColourDiff; ++i) {
      weight_lut_[i] = std::exp(-static_cast<float>(i) / params.sigma);
    }
    for (int i = -255; i <= 255; ++i) weight_by_grey_diff_[i + 255] = weight_lut_[3 * std::abs(i)];
    lut_sigma_ = params.sigma;
  }
  disparity_px->copyTo(source_px_);
  markJumps(source_px_, params.jump_px);
  dilateJumps(params.band_px);
  std::size_t band_px = 0;
  for (std::uint8_t b : band_) band_px += b;
  stride_px_ = chooseStride(band_px, band_.size(), params.radius_px, params.budget);
  if (guide.channels() == 3) {
    markGuideKeys<3>(guide);
    refineBand<3>(guide, params.radius_px, disparity_px);
  } else {
    markGuideKeys<1>(guide);
    refineBand<1>(guide, params.radius_px, disparity_px);
  }
}

}  // namespace deepnav
