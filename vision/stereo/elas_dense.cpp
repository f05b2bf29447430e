#include "vision/stereo/elas_dense.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>

#include "vision/stereo/sad16.h"

namespace deepnav {
namespace {

// Bits lo .. hi (disparities, inclusive) of the 64-bit word holding disparities first .. first + 63.
std::uint64_t bitsBetween(int first, int lo, int hi) {
  lo = std::max(lo - first, 0);
  hi = std::min(hi - first, 63);
  if (lo > hi) return 0;
  const std::uint64_t upto_hi = hi == 63 ? ~std::uint64_t{0} : (std::uint64_t{2} << hi) - 1;
  return upto_hi & ~((std::uint64_t{1} << lo) - 1);
}

// std::ceil / std::floor of a float with |x| < 2^24, as int: a truncation and a compare instead of
// the bit manipulation the compiler inlines for ceilf / floorf without SSE4.1.
int ceilToInt(float x) {
  const int t = static_cast<int>(x);
  return static_cast<float>(t) < x ? t + 1 : t;
}

int floorToInt(float x) {
  const int t = static_cast<int>(x);
  return static_cast<float>(t) > x ? t - 1 : t;
}

}  // namespace

bool ElasDenseMatcher::allocate(const ElasParams& params) {
  if (params.beta <= 0.0f || params.gamma <= 0.0f || params.sigma_px <= 0.0f ||
      params.sradius_px < 0 || params.num_disparities > 64 * ElasCandidates::kWords) {
    return false;
  }
  params_ = params;
  prior_bonus_.resize(static_cast<std::size_t>(params.sradius_px) * kPriorSteps + 1);
  for (std::size_t k = 0; k < prior_bonus_.size(); ++k) {
    const double x = static_cast<double>(k) / kPriorSteps;
    const double gauss = std::exp(-x * x / (2.0 * params.sigma_px * params.sigma_px));
    prior_bonus_[k] =
        static_cast<int>(std::lround(-std::log1p(gauss / params.gamma) / params.beta));
  }
  return true;
}

int ElasDenseMatcher::priorBonus(int d, float mu) const {
  const float x = std::fabs(static_cast<float>(d) - mu);
  if (mu < 0.0f || x > static_cast<float>(params_.sradius_px)) return 0;
  return prior_bonus_[static_cast<int>(x * kPriorSteps + 0.5f)];
}

void ElasDenseMatcher::match(const ElasDescriptorImage& ref, const ElasDescriptorImage& other,
                             bool view_right, const cv::Mat& mean_px,
                             const ElasCandidates& candidates, cv::Mat* disparity_px,
                             cv::Mat* subpixel_px) const {
  for (int v = 0; v < ref.height(); ++v) {
    matchRow(ref, other, view_right, mean_px, candidates, v, disparity_px->ptr<float>(v),
             subpixel_px != nullptr ? subpixel_px->ptr<float>(v) : nullptr);
  }
}

inline float ElasDenseMatcher::matchPixel(const std::uint8_t* ref_row, const std::uint8_t* other_row, bool view_right,
                                   int width, float mu, const std::uint64_t* cell, int words, int u,
                                   float* subpixel) const {
  constexpr std::ptrdiff_t kBytes = ElasDescriptorImage::kBytes;
  const std::uint8_t* f_ref = ref_row + u * kBytes;
  if (descriptorTexture(f_ref) < params_.match_texture) return -1.0f;
  const std::ptrdiff_t dir = view_right ? kBytes : -kBytes;  // other pixel = u + (+-) d
  const std::uint8_t* f_other = other_row + u * kBytes;      // at d = 0
  const int d_last = std::min(params_.num_disparities - 1, view_right ? width - 1 - u : u);
  const float sradius = static_cast<float>(params_.sradius_px);
  int best_d = -1;
  int best_cost = INT_MAX;
  // 1) the band |d - mu| <= sradius, with the prior bonus (priorBonus() with mu >= 0 known)
  int band_lo = 1, band_hi = 0;
  if (mu >= 0.0f) {
    band_lo = std::max(0, ceilToInt(mu - sradius));
    band_hi = std::min(d_last, floorToInt(mu + sradius));
    const std::uint8_t* f = f_other + band_lo * dir;
    for (int d = band_lo; d <= band_hi; ++d, f += dir) {
      const float x = std::fabs(static_cast<float>(d) - mu);
      const int bonus = x > sradius ? 0 : prior_bonus_[static_cast<int>(x * kPriorSteps + 0.5f)];
      const int c = sad16(f_ref, f) + bonus;
      if (c < best_cost) {
        best_cost = c;
        best_d = d;
      }
    }
  }
  // 2) the support disparities of the cell outside the band, likelihood only
  for (int w = 0; w < words && 64 * w <= d_last; ++w) {
    std::uint64_t m = cell[w] & bitsBetween(64 * w, 0, d_last) & ~bitsBetween(64 * w, band_lo, band_hi);
    for (; m != 0; m &= m - 1) {
      const int d = 64 * w + std::countr_zero(m);
      const int c = sad16(f_ref, f_other + d * dir);
      if (c < best_cost) {
        best_cost = c;
        best_d = d;
      }
    }
  }
  if (best_d < 0) return -1.0f;
  if (subpixel != nullptr) {
    subpixel[u] = 0.0f;
    if (best_d > 0 && best_d < d_last) {
      // parabola through (d-1, d, d+1): vertex offset (c- - c+) / (2 (c- - 2 c + c+))
      const int c_minus = sad16(f_ref, f_other + (best_d - 1) * dir) + priorBonus(best_d - 1, mu);
      const int c_plus = sad16(f_ref, f_other + (best_d + 1) * dir) + priorBonus(best_d + 1, mu);
      const int curvature = c_minus - 2 * best_cost + c_plus;
      if (curvature > 0) {
        subpixel[u] = std::clamp(0.5f * static_cast<float>(c_minus - c_plus) / curvature, -0.5f, 0.5f);
      }
    }
  }
  return static_cast<float>(best_d);
}

// The row is walked cell by cell of the candidate grid (no division per pixel).
void ElasDenseMatcher::matchRow(const ElasDescriptorImage& ref, const ElasDescriptorImage& other,
                                bool view_right, const cv::Mat& mean_px,
                                const ElasCandidates& candidates, int v, float* out,
                                float* subpixel) const {
  const int width = ref.width();
  const int grid = candidates.gridSize();
  const float* mean_row = mean_px.ptr<float>(v);
  const std::uint8_t* ref_row = ref.at(0, v);
  const std::uint8_t* other_row = other.at(0, v);
  for (int u0 = 0; u0 < width; u0 += grid) {
    const std::uint64_t* cell = candidates.cellMask(u0, v);
    const int u1 = std::min(width, u0 + grid);
    for (int u = u0; u < u1; ++u) {
      out[u] = matchPixel(ref_row, other_row, view_right, width, mean_row[u], cell, candidates.words(), u,
                          subpixel);
    }
  }
}

}  // namespace deepnav
