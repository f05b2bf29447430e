#include "vision/stereo/elas_dense.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <opencv2/core/hal/intrin.hpp>

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

// Bits 0 .. d_last (d_last in [0, 63]) of one word.
std::uint64_t bitsUpTo(int d_last) { return ~std::uint64_t{0} >> (63 - d_last); }

// Bits lo .. lo + n - 1 of one word (lo + n <= 64); none when n <= 0.
std::uint64_t bitsFrom(int lo, int n) { return n > 0 ? (~std::uint64_t{0} >> (64 - n)) << lo : 0; }

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

bool ElasDenseMatcher::allocate(const ElasParams& params, int width_px) {
  if (params.beta <= 0.0f || params.gamma <= 0.0f || params.sigma_px <= 0.0f ||
      params.sradius_px < 0 || params.num_disparities > 64 * ElasCandidates::kWords || width_px < 1) {
    return false;
  }
  params_ = params;
  width_px_ = width_px;
  zero_bonus_index_ = params.sradius_px * kPriorSteps + 1;
  prior_bonus_.assign(static_cast<std::size_t>(zero_bonus_index_) + 1, 0);
  for (int k = 0; k < zero_bonus_index_; ++k) {
    const double x = static_cast<double>(k) / kPriorSteps;
    const double gauss = std::exp(-x * x / (2.0 * params.sigma_px * params.sigma_px));
    prior_bonus_[k] =
        static_cast<int>(std::lround(-std::log1p(gauss / params.gamma) / params.beta));
  }
  band_slots_ = 2 * params.sradius_px + 1;
  band_lo_.assign(static_cast<std::size_t>(width_px), 1);
  band_hi_.assign(static_cast<std::size_t>(width_px), 0);
  bonus_index_.assign(static_cast<std::size_t>(band_slots_) * width_px, zero_bonus_index_);
  parabola_minus_.assign(static_cast<std::size_t>(width_px), 0);
  parabola_centre_.assign(static_cast<std::size_t>(width_px), 0);
  parabola_plus_.assign(static_cast<std::size_t>(width_px), 0);
  return true;
}

int ElasDenseMatcher::priorBonus(int d, float mu) const {
  if (mu < 0.0f) return 0;
  return prior_bonus_[bonusIndex(d, mu)];
}

int ElasDenseMatcher::bonusIndex(int d, float mu) const {
  const float x = std::fabs(static_cast<float>(d) - mu);
  if (x > static_cast<float>(params_.sradius_px)) return zero_bonus_index_;
  return static_cast<int>(x * kPriorSteps + 0.5f);
}

// Scalar reference of the vector loop below, also its tail.
void ElasDenseMatcher::prepareRange(const float* mean_row, bool view_right, int width, int u_begin,
                                    int u_end) {
  const float sradius = static_cast<float>(params_.sradius_px);
  for (int u = u_begin; u < u_end; ++u) {
    const float mu = mean_row[u];
    const int d_last = std::min(params_.num_disparities - 1, view_right ? width - 1 - u : u);
    band_lo_[u] = mu >= 0.0f ? std::max(0, ceilToInt(mu - sradius)) : 1;
    band_hi_[u] = mu >= 0.0f ? std::min(d_last, floorToInt(mu + sradius)) : 0;
    for (int k = 0; k < band_slots_; ++k) {
      bonus_index_[static_cast<std::size_t>(k) * width + u] = bonusIndex(band_lo_[u] + k, mu);
    }
  }
}

void ElasDenseMatcher::prepareRow(const float* mean_row, bool view_right, int width) {
  int u = 0;
#if CV_SIMD128
  const cv::v_float32x4 sradius = cv::v_setall_f32(static_cast<float>(params_.sradius_px));
  const cv::v_float32x4 zero_f = cv::v_setzero_f32();
  const cv::v_float32x4 steps = cv::v_setall_f32(static_cast<float>(kPriorSteps));
  const cv::v_float32x4 half = cv::v_setall_f32(0.5f);
  const cv::v_int32x4 lane(0, 1, 2, 3);
  const cv::v_int32x4 last_d = cv::v_setall_s32(params_.num_disparities - 1);
  const cv::v_int32x4 zero_index = cv::v_setall_s32(zero_bonus_index_);
  const auto asInt = [](const cv::v_float32x4& mask) { return cv::v_reinterpret_as_s32(mask); };
  for (; u + 4 <= width; u += 4) {
    const cv::v_float32x4 mu = cv::v_load(mean_row + u);
    const cv::v_int32x4 uu = cv::v_setall_s32(u) + lane;
    const cv::v_int32x4 d_last = cv::v_min(last_d, view_right ? cv::v_setall_s32(width - 1) - uu : uu);
    // ceilToInt / floorToInt: truncation, then -1 (all bits of a true mask) corrects it
    const cv::v_float32x4 lo_f = mu - sradius, hi_f = mu + sradius;
    const cv::v_int32x4 lo_t = cv::v_trunc(lo_f), hi_t = cv::v_trunc(hi_f);
    const cv::v_int32x4 lo = cv::v_max(cv::v_setzero_s32(), lo_t - asInt(cv::v_cvt_f32(lo_t) < lo_f));
    const cv::v_int32x4 hi = cv::v_min(d_last, hi_t + asInt(cv::v_cvt_f32(hi_t) > hi_f));
    const cv::v_int32x4 has_prior = asInt(mu >= zero_f);
    const cv::v_int32x4 band_lo = cv::v_select(has_prior, lo, cv::v_setall_s32(1));
    cv::v_store(band_lo_.data() + u, band_lo);
    cv::v_store(band_hi_.data() + u, cv::v_select(has_prior, hi, cv::v_setzero_s32()));
    for (int k = 0; k < band_slots_; ++k) {
      const cv::v_float32x4 x = cv::v_abs(cv::v_cvt_f32(band_lo + cv::v_setall_s32(k)) - mu);
      const cv::v_int32x4 index = cv::v_trunc(x * steps + half);
      cv::v_store(bonus_index_.data() + static_cast<std::size_t>(k) * width + u,
                  cv::v_select(asInt(x > sradius), zero_index, index));
    }
  }
#endif
  prepareRange(mean_row, view_right, width, u, width);
}

void ElasDenseMatcher::match(const ElasDescriptorImage& ref, const ElasDescriptorImage& other,
                             bool view_right, const cv::Mat& mean_px,
                             const ElasCandidates& candidates, cv::Mat* disparity_px,
                             cv::Mat* subpixel_px) {
  for (int v = 0; v < ref.height(); ++v) {
    prepareRow(mean_px.ptr<float>(v), view_right, ref.width());
    float* subpixel = subpixel_px != nullptr ? subpixel_px->ptr<float>(v) : nullptr;
    if (view_right) {
      matchRow<true>(ref, other, mean_px, candidates, v, disparity_px->ptr<float>(v), subpixel);
    } else {
      matchRow<false>(ref, other, mean_px, candidates, v, disparity_px->ptr<float>(v), subpixel);
    }
  }
}

// The search keeps one integer key per candidate, cost * 512 + class * 256 + d (class 0: band, 1:
// support), and takes the smallest: the smallest cost, among equal costs a band candidate before a
// support candidate, then the smaller disparity. That is the candidate a scan of the band and then of
// the supports in increasing d with strict improvement picks, found without a branch per candidate
// (the data-dependent branch of that scan was mispredicted on about every other candidate).
template <bool kViewRight>
[[gnu::always_inline]] inline float ElasDenseMatcher::matchPixel(const std::uint8_t* ref_row, const std::uint8_t* other_row, int width,
                                          float mu, const std::uint64_t* cell, int words, int u,
                                          float* subpixel) {
  constexpr std::ptrdiff_t kBytes = ElasDescriptorImage::kBytes;
  constexpr std::ptrdiff_t kDir = kViewRight ? kBytes : -kBytes;  // other pixel = u + (+-) d
  constexpr int kSupportClass = 256;
  constexpr int kCachedBand = 16;  // band costs kept for the sub-pixel step (the band is 2 sradius + 1 wide)
  const std::uint8_t* f_ref = ref_row + u * kBytes;
  if (descriptorTexture(f_ref) < params_.match_texture) return -1.0f;
  const std::uint8_t* f_other = other_row + u * kBytes;  // at d = 0
  const int d_last = std::min(params_.num_disparities - 1, kViewRight ? width - 1 - u : u);
  int best_key = INT_MAX;
  int band_cost[kCachedBand];
  // 1) the band |d - mu| <= sradius (empty without a prior), with the prior bonus of prepareRow();
  // a band wider than the prepared slots (float rounding of mu +- sradius) takes bonusIndex()
  const int band_lo = band_lo_[u];
  const int band_n = band_hi_[u] - band_lo + 1;
  const int cached_n = std::min({band_n, band_slots_, kCachedBand});
  const std::uint8_t* f_lo = f_other + band_lo * kDir;
  const int* bonus_index = bonus_index_.data() + u;
  for (int k = 0; k < cached_n; ++k) {
    const int c = sad16(f_ref, f_lo + k * kDir) + prior_bonus_[bonus_index[static_cast<std::ptrdiff_t>(k) * width]];
    band_cost[k] = c;
    best_key = std::min(best_key, c * 512 + band_lo + k);
  }
  for (int k = std::max(cached_n, 0); k < band_n; ++k) {
    const int d = band_lo + k;
    const int index = k < band_slots_ ? bonus_index[static_cast<std::ptrdiff_t>(k) * width] : bonusIndex(d, mu);
    best_key = std::min(best_key, (sad16(f_ref, f_lo + k * kDir) + prior_bonus_[index]) * 512 + d);
  }
  // 2) the support disparities of the cell outside the band, likelihood only
  const auto support = [&](std::uint64_t m, int first) {
    for (; m != 0; m &= m - 1) {
      const int d = first + std::countr_zero(m);
      best_key = std::min(best_key, sad16(f_ref, f_other + d * kDir) * 512 + kSupportClass + d);
    }
  };
  if (words == 1) {
    support(cell[0] & bitsUpTo(d_last) & ~bitsFrom(band_lo, band_n), 0);
  } else {
    for (int w = 0; w < words && 64 * w <= d_last; ++w) {
      support(cell[w] & bitsBetween(64 * w, 0, d_last) & ~bitsBetween(64 * w, band_lo, band_lo + band_n - 1),
              64 * w);
    }
  }
  if (best_key == INT_MAX) return -1.0f;
  const int best_d = best_key & 255;
  if (subpixel != nullptr) {
    const int best_cost = best_key >> 9;  // arithmetic shift: floor(key / 512), also for negative costs
    // cost with the prior bonus of a neighbour of best_d: from the band when it was there
    const auto cost = [&](int d) {
      const int k = d - band_lo;
      if (k >= 0 && k < cached_n) return band_cost[k];
      return sad16(f_ref, f_other + d * kDir) + priorBonus(d, mu);
    };
    // the parabola's costs, its vertex computed for the whole row by subpixelRow(); none at the ends of
    // the range (a zero curvature gives 0)
    const bool inside = best_d > 0 && best_d < d_last;
    parabola_minus_[u] = inside ? cost(best_d - 1) : best_cost;
    parabola_centre_[u] = best_cost;
    parabola_plus_[u] = inside ? cost(best_d + 1) : best_cost;
  }
  return static_cast<float>(best_d);
}

// Vertex offset of the parabola through (d-1, d, d+1): (c- - c+) / (2 (c- - 2 c + c+)), clamped to
// [-0.5, 0.5], 0 where the curvature is not positive. Out of matchPixel() so that the division runs 4
// pixels at a time (it was the matcher's longest latency, once per pixel): the same float operations.
void ElasDenseMatcher::subpixelRow(const float* disparity, int width, float* subpixel) const {
  const int* c_minus = parabola_minus_.data();
  const int* c_centre = parabola_centre_.data();
  const int* c_plus = parabola_plus_.data();
  int u = 0;
#if CV_SIMD128
  const cv::v_float32x4 half = cv::v_setall_f32(0.5f), neg_half = cv::v_setall_f32(-0.5f);
  const cv::v_int32x4 zero = cv::v_setzero_s32();
  for (; u + 4 <= width; u += 4) {
    const cv::v_int32x4 m = cv::v_load(c_minus + u), c = cv::v_load(c_centre + u), p = cv::v_load(c_plus + u);
    const cv::v_int32x4 curvature = m - (c + c) + p;
    const cv::v_float32x4 offset = half * cv::v_cvt_f32(m - p) / cv::v_cvt_f32(curvature);
    const cv::v_float32x4 clamped = cv::v_min(cv::v_max(offset, neg_half), half);
    const cv::v_int32x4 matched = cv::v_reinterpret_as_s32(cv::v_load(disparity + u) >= cv::v_setzero_f32());
    const cv::v_int32x4 use = (curvature > zero) & matched;
    cv::v_store(subpixel + u, cv::v_select(cv::v_reinterpret_as_f32(use), clamped, cv::v_setzero_f32()));
  }
#endif
  for (; u < width; ++u) {
    const int curvature = c_minus[u] - 2 * c_centre[u] + c_plus[u];
    subpixel[u] = disparity[u] >= 0.0f && curvature > 0
                      ? std::clamp(0.5f * static_cast<float>(c_minus[u] - c_plus[u]) / curvature, -0.5f, 0.5f)
                      : 0.0f;
  }
}

// The row is walked cell by cell of the candidate grid (no division per pixel).
template <bool kViewRight>
void ElasDenseMatcher::matchRow(const ElasDescriptorImage& ref, const ElasDescriptorImage& other,
                                const cv::Mat& mean_px, const ElasCandidates& candidates, int v, float* out,
                                float* subpixel) {
  const int width = ref.width();
  const int grid = candidates.gridSize();
  const int words = candidates.words();
  const float* mean_row = mean_px.ptr<float>(v);
  const std::uint8_t* ref_row = ref.at(0, v);
  const std::uint8_t* other_row = other.at(0, v);
  for (int u0 = 0; u0 < width; u0 += grid) {
    const std::uint64_t* cell = candidates.cellMask(u0, v);
    const int u1 = std::min(width, u0 + grid);
    for (int u = u0; u < u1; ++u) {
      out[u] = matchPixel<kViewRight>(ref_row, other_row, width, mean_row[u], cell, words, u, subpixel);
    }
  }
  if (subpixel != nullptr) subpixelRow(out, width, subpixel);
}

}  // namespace deepnav
