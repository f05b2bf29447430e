#pragma once
#include <opencv2/core.hpp>
#include <vector>

#include "vision/stereo/elas_candidates.h"
#include "vision/stereo/elas_descriptor.h"
#include "vision/stereo/elas_params.h"

namespace deepnav {

// Dense MAP disparity of ELAS (Geiger et al. 2010, MAP disparity): for every pixel,
//   d* = argmin_d  beta * |f_ref - f_other(d)|_1  -  log(gamma + exp(-(d - mu)^2 / (2 sigma^2)))
// (the negative log posterior) over the candidates d with |d - mu| <= sradius or d in the cell's
// support set N_S. Costs are kept in descriptor units: the prior becomes an integer bonus
//   P(x) = -log(1 + exp(-x^2 / (2 sigma^2)) / gamma) / beta   for x = |d - mu| <= sradius
// (the constant log(gamma) shared by all candidates dropped), 0 elsewhere.
class ElasDenseMatcher {
 public:
  bool allocate(const ElasParams& params, int width_px);
  // view_right: ref is the right image, its pixel (u, v) matches other's (u + d, v).
  // mean_px: ElasPrior::mean() of the ref view. Writes integer disparities (CV_32F, -1 where
  // unmatched) and, when subpixel_px is not null, the sub-pixel correction in [-0.5, 0.5] of each
  // (kept apart so that the segment filters see clean integer steps).
  void match(const ElasDescriptorImage& ref, const ElasDescriptorImage& other, bool view_right,
             const cv::Mat& mean_px, const ElasCandidates& candidates, cv::Mat* disparity_px,
             cv::Mat* subpixel_px);

 private:
  static constexpr int kPriorSteps = 16;  // resolution of the prior table: 1/16 px

  // The band [band_lo_, band_hi_] of every pixel of a row and the prior_bonus_ index of each of its
  // disparities, 4 pixels at a time in float lanes (the same float operations as priorBonus()).
  void prepareRow(const float* mean_row, bool view_right, int width);
  void prepareRange(const float* mean_row, bool view_right, int width, int u_begin, int u_end);
  template <bool kViewRight>
  void matchRow(const ElasDescriptorImage& ref, const ElasDescriptorImage& other, const cv::Mat& mean_px,
                const ElasCandidates& candidates, int v, float* out, float* subpixel);
  // The disparity of ref pixel u (-1 when none) and, when subpixel is not null, the costs at its
  // d - 1, d, d + 1 for subpixelRow() (subpixel itself is not written here).
  template <bool kViewRight>
  float matchPixel(const std::uint8_t* ref_row, const std::uint8_t* other_row, int width, float mu,
                   const std::uint64_t* cell, int words, int u, float* subpixel);
  // subpixel[u] of the row from the parabola costs matchPixel() left (0 where disparity[u] < 0)
  void subpixelRow(const float* disparity, int width, float* subpixel) const;
  int priorBonus(int d, float mu) const;
  int bonusIndex(int d, float mu) const;

  ElasParams params_;
  int width_px_ = 0;
  int band_slots_ = 1;            // 2 sradius + 1: the widest band (a wider one takes bonusIndex())
  int zero_bonus_index_ = 0;      // index of the 0 after the table: d outside the radius
  std::vector<int> prior_bonus_;  // P(k / kPriorSteps), k = 0 .. sradius * kPriorSteps, then 0
  std::vector<int> band_lo_;      // per pixel of the row being matched
  std::vector<int> band_hi_;      // < band_lo_ when the pixel has no prior (mu < 0)
  std::vector<int> bonus_index_;  // [k * width + u]: prior_bonus_ index of d = band_lo_[u] + k
  // per pixel of the row: the costs at best d - 1, d, d + 1 (all three the best cost at the range's ends)
  std::vector<int> parabola_minus_, parabola_centre_, parabola_plus_;
};

}  // namespace deepnav
