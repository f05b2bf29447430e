#include "vision/stereo/elas_dense.h"

#include <algorithm>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>

#include "vision/stereo/sad16.h"

namespace deepnav {

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
  return prior_bonus_[static_cast<std::size_t>(x * kPriorSteps + 0.5f)];
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

void ElasDenseMatcher::matchRow(const ElasDescriptorImage& ref, const ElasDescriptorImage& other,
                                bool view_right, const cv::Mat& mean_px,
                                const ElasCandidates& candidates, int v, float* out,
                                float* subpixel) const {
  constexpr std::ptrdiff_t kBytes = ElasDescriptorImage::kBytes;
  const int width = ref.width();
  const int words = candidates.words();
  const float sradius = static_cast<float>(params_.sradius_px);
  const float* mean_row = mean_px.ptr<float>(v);
  const std::uint8_t* ref_row = ref.at(0, v);
  const std::uint8_t* other_row = other.at(0, v);
  const std::ptrdiff_t dir = view_right ? kBytes : -kBytes;  // other pixel = u + (+-) d
  for (int u = 0; u < width; ++u) {
    out[u] = -1.0f;
    const std::uint8_t* f_ref = ref_row + u * kBytes;
    if (descriptorTexture(f_ref) < params_.match_texture) continue;
    const std::uint8_t* f_other = other_row + u * kBytes;  // at d = 0
    const int d_last = std::min(params_.num_disparities - 1, view_right ? width - 1 - u : u);
    const float mu = mean_row[u];
    int best_d = -1;
    int best_cost = INT_MAX;
    // 1) the band |d - mu| <= sradius, with the prior bonus
    int band_lo = 1, band_hi = 0;
    if (mu >= 0.0f) {
      band_lo = std::max(0, static_cast<int>(std::ceil(mu - sradius)));
      band_hi = std::min(d_last, static_cast<int>(std::floor(mu + sradius)));
      for (int d = band_lo; d <= band_hi; ++d) {
        const int c = sad16(f_ref, f_other + d * dir) + priorBonus(d, mu);
        if (c < best_cost) {
          best_cost = c;
          best_d = d;
        }
      }
    }
    // 2) the support disparities of the cell outside the band, likelihood only
    const std::uint64_t* cell = candidates.cellMask(u, v);
    for (int w = 0; w < words && 64 * w <= d_last; ++w) {
      std::uint64_t m = cell[w];
      if (d_last < 64 * w + 63) m &= (std::uint64_t{2} << (d_last - 64 * w)) - 1;
      for (; m != 0; m &= m - 1) {
        const int d = 64 * w + std::countr_zero(m);
        if (d >= band_lo && d <= band_hi) continue;
        const int c = sad16(f_ref, f_other + d * dir);
        if (c < best_cost) {
          best_cost = c;
          best_d = d;
        }
      }
    }
    if (best_d < 0) continue;
    out[u] = static_cast<float>(best_d);
    if (subpixel == nullptr) continue;
    subpixel[u] = 0.0f;
    if (best_d > 0 && best_d < d_last) {
      // parabola through (d-1, d, d+1): vertex offset (c- - c+) / (2 (c- - 2 c + c+))
      const int c_minus = sad16(f_ref, f_other + (best_d - 1) * dir) + priorBonus(best_d - 1, mu);
      const int c_plus = sad16(f_ref, f_other + (best_d + 1) * dir) + priorBonus(best_d + 1, mu);
      const int curvature = c_minus - 2 * best_cost + c_plus;
      if (curvature > 0) {
        subpixel[u] =
            std::clamp(0.5f * static_cast<float>(c_minus - c_plus) / curvature, -0.5f, 0.5f);
      }
    }
  }
}

}  // namespace deepnav
