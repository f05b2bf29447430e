#include "vision/orbvo/stereo_feature_matcher.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

namespace deepnav {
namespace {

constexpr int kMaxSearch = 8;                 // of StereoMatchConfig::sad_search_px
constexpr int kMaxWindows = 2 * kMaxSearch + 1;  // right windows compared with one left window

int windowSum(const cv::Mat& image, int u, int v, int w) {
  int sum = 0;
  for (int dy = -w; dy <= w; ++dy) {
    const std::uint8_t* row = image.ptr<std::uint8_t>(v + dy);
    for (int dx = -w; dx <= w; ++dx) sum += row[u + dx];
  }
  return sum;
}

// Zero-mean SAD of the (2w+1)^2 window centred at (ul, vl) of the left image (pixel sum left_sum)
// against the N windows
// centred at (ur + k, vr), k = 0 .. N - 1, of the right one (all inside): the two cameras of a
// housing rarely share gain and vignetting. Each cost is the same chain of double operations as a
// window on its own; the N chains run side by side in registers, so that they overlap instead of
// each waiting on its own additions (about 4 cycles each, 121 of them for w = 5).
template <int N>
void zeroMeanSads(const cv::Mat& left, const cv::Mat& right, int ul, int vl, int left_sum, int ur, int vr,
                  int w, double* cost) {
  const int area = (2 * w + 1) * (2 * w + 1);
  std::array<double, N> offset;
  std::array<double, N> sad{};
  for (int k = 0; k < N; ++k) {
    offset[k] = static_cast<double>(left_sum - windowSum(right, ur + k, vr, w)) / area;
  }
  for (int dy = -w; dy <= w; ++dy) {
    const std::uint8_t* lrow = left.ptr<std::uint8_t>(vl + dy) + ul;
    const std::uint8_t* rrow = right.ptr<std::uint8_t>(vr + dy) + ur;
    for (int dx = -w; dx <= w; ++dx) {
      const int l = lrow[dx];
#pragma GCC unroll 17
      for (int k = 0; k < N; ++k) sad[k] += std::abs(l - rrow[dx + k] - offset[k]);
    }
  }
  std::copy(sad.begin(), sad.end(), cost);
}

using ZeroMeanSadsFn = void (*)(const cv::Mat&, const cv::Mat&, int, int, int, int, int, int, double*);

template <std::size_t... I>
constexpr std::array<ZeroMeanSadsFn, sizeof...(I)> zeroMeanSadsTable(std::index_sequence<I...>) {
  return {&zeroMeanSads<static_cast<int>(I) + 1>...};
}

// [n - 1]: the costs of n windows side by side.
constexpr auto kZeroMeanSads = zeroMeanSadsTable(std::make_index_sequence<kMaxWindows>());

}  // namespace

bool StereoFeatureMatcher::init(const StereoMatchConfig& config, const StereoRig& rig,
                                int max_features, double level_scale_factor) {
  if (config.row_band_px < 0.0 || config.min_depth_m <= 0.0 ||
      config.max_depth_m <= config.min_depth_m || config.max_hamming < 0 || config.ratio <= 0.0 ||
      config.ratio > 1.0 || config.max_level_difference < 0 || config.sad_half_window_px < 1 ||
      config.sad_half_window_px > 15 || config.sad_search_px < 1 || config.sad_search_px > kMaxSearch ||
      config.sad_distinct_ratio <= 0.0 || config.sad_distinct_ratio > 1.0 ||
      rig.baseline_m <= 0.0 || rig.fx_px <= 0.0 || rig.height_px < 1 || max_features < 1 ||
      level_scale_factor < 1.0) {
    return false;
  }
  config_ = config;
  rig_ = rig;
  level_scale_factor_ = level_scale_factor;
  min_disparity_px_ = rig.fx_px * rig.baseline_m / config.max_depth_m;
  max_disparity_px_ = rig.fx_px * rig.baseline_m / config.min_depth_m;
  row_start_.assign(rig.height_px + 1, 0);
  sorted_right_.assign(max_features, 0);
  best_right_.assign(max_features, -1);
  best_distance_.assign(max_features, 0);
  right_owner_.assign(max_features, -1);
  owner_distance_.assign(max_features, 0);
  return true;
}

// Counting sort of the right corners by row.
void StereoFeatureMatcher::indexRightRows(const std::vector<OrbFeature>& right) {
  const int rows = rig_.height_px;
  std::fill(row_start_.begin(), row_start_.end(), 0);
  for (const OrbFeature& f : right) {
    const int r = std::clamp(static_cast<int>(std::lround(f.v_px)), 0, rows - 1);
    ++row_start_[r + 1];
  }
  for (int r = 0; r < rows; ++r) row_start_[r + 1] += row_start_[r];
  // Fill with a moving cursor per row; row_start_ is shifted back afterwards.
  for (int i = 0; i < static_cast<int>(right.size()); ++i) {
    const int r = std::clamp(static_cast<int>(std::lround(right[i].v_px)), 0, rows - 1);
    sorted_right_[row_start_[r]++] = i;
  }
  for (int r = rows; r > 0; --r) row_start_[r] = row_start_[r - 1];
  row_start_[0] = 0;
}

int StereoFeatureMatcher::bestRightCandidate(const OrbFeature& lf, const OrbDescriptor& ld,
                                             const std::vector<OrbFeature>& right,
                                             const std::vector<OrbDescriptor>& right_desc,
                                             int* distance) {
  const double band = config_.row_band_px * std::pow(level_scale_factor_, lf.level);
  const int r0 = std::max(0, static_cast<int>(std::floor(lf.v_px - band)));
  const int r1 = std::min(rig_.height_px - 1, static_cast<int>(std::ceil(lf.v_px + band)));
  int best = std::numeric_limits<int>::max();
  int second = std::numeric_limits<int>::max();
  int best_index = -1;
  for (int k = row_start_[r0]; k < row_start_[r1 + 1]; ++k) {
    const int j = sorted_right_[k];
    const OrbFeature& rf = right[j];
    const double disparity = lf.u_px - rf.u_px;
    if (disparity < min_disparity_px_ - 1.0 || disparity > max_disparity_px_ + 1.0) continue;
    if (std::abs(rf.v_px - lf.v_px) > band ||
        std::abs(rf.level - lf.level) > config_.max_level_difference)
      continue;
    const int d = hammingDistance(ld, right_desc[j]);
    if (d < best) {
      second = best;
      best = d;
      best_index = j;
    } else if (d < second) {
      second = d;
    }
  }
  if (best_index < 0) {
    ++stats_.no_candidate;
    return -1;
  }
  if (best > config_.max_hamming ||
      (second != std::numeric_limits<int>::max() && best >= config_.ratio * second)) {
    ++stats_.descriptor;
    return -1;
  }
  *distance = best;
  return best_index;
}

int StereoFeatureMatcher::match(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                const std::vector<OrbFeature>& left,
                                const std::vector<OrbDescriptor>& left_desc,
                                const std::vector<OrbFeature>& right,
                                const std::vector<OrbDescriptor>& right_desc,
                                std::vector<float>* u_right_px,
                                std::vector<Eigen::Vector3d>* p_in_cam_m) {
  const int n_left = std::min(static_cast<int>(left.size()), static_cast<int>(best_right_.size()));
  const int n_right =
      std::min(static_cast<int>(right.size()), static_cast<int>(sorted_right_.size()));
  stats_ = StereoMatchStats();
  u_right_px->assign(left.size(), -1.0f);
  p_in_cam_m->assign(left.size(), Eigen::Vector3d::Zero());
  if (n_left == 0 || n_right == 0) return 0;
  indexRightRows(right);
  std::fill_n(right_owner_.begin(), n_right, -1);
  for (int i = 0; i < n_left; ++i) {
    best_right_[i] =
        bestRightCandidate(left[i], left_desc[i], right, right_desc, &best_distance_[i]);
    const int j = best_right_[i];
    if (j < 0) continue;
    if (right_owner_[j] < 0 || best_distance_[i] < owner_distance_[j]) {
      right_owner_[j] = i;
      owner_distance_[j] = best_distance_[i];
    }
  }
  int matches = 0;
  for (int i = 0; i < n_left; ++i) {
    const int j = best_right_[i];
    if (j < 0) continue;
    if (right_owner_[j] != i) {
      ++stats_.duplicate;
      continue;
    }
    double u_right = 0.0;
    if (!refineRightColumn(left_grey, right_grey, left[i].u_px, left[i].v_px, right[j].u_px,
                           &u_right)) {
      ++stats_.refinement;
      continue;
    }
    const double disparity = left[i].u_px - u_right;
    if (disparity < min_disparity_px_ || disparity > max_disparity_px_) {
      ++stats_.depth;
      continue;
    }
    (*u_right_px)[i] = static_cast<float>(u_right);
    (*p_in_cam_m)[i] = triangulateStereo(rig_, left[i].u_px, left[i].v_px, disparity);
    ++matches;
  }
  return matches;
}

bool StereoFeatureMatcher::refineRightColumn(const cv::Mat& left_grey, const cv::Mat& right_grey,
                                             double u_px, double v_px, double u_right_guess_px,
                                             double* u_right_px) const {
  const int w = config_.sad_half_window_px;
  const int search = config_.sad_search_px;
  const int ul = static_cast<int>(std::lround(u_px));
  const int v = static_cast<int>(std::lround(v_px));
  // The right window keeps the left one's rounding offset.
  const int ur = static_cast<int>(std::lround(u_right_guess_px - (u_px - ul)));
  // The window must fit at rows v-1..v+1 (the row check) and every searched column.
  if (v - w - 1 < 0 || v + w + 1 >= left_grey.rows || ul - w < 0 || ul + w >= left_grey.cols)
    return false;
  if (ur - search - w < 0 || ur + search + w >= right_grey.cols) return false;
  double cost[kMaxWindows];
  const int left_sum = windowSum(left_grey, ul, v, w);  // one left window for every cost below
  kZeroMeanSads[2 * search](left_grey, right_grey, ul, v, left_sum, ur - search, v, w, cost);
  int best_k = -search;
  for (int k = -search; k <= search; ++k) {
    if (cost[k + search] < cost[best_k + search]) best_k = k;
  }
  if (best_k == -search || best_k == search) return false;
  const double c0 = cost[best_k + search];
  // A true match stands out of its neighbourhood; a flat or repetitive row does not.
  if (c0 > config_.sad_distinct_ratio * std::min(cost[0], cost[2 * search])) return false;
  // Rectified rows: the right window one row up or down must fit worse (a corner matched on the
  // wrong row fits better towards its true row).
  double row_cost = 0.0;
  zeroMeanSads<1>(left_grey, right_grey, ul, v, left_sum, ur + best_k, v - 1, w, &row_cost);
  if (row_cost <= c0) return false;
  zeroMeanSads<1>(left_grey, right_grey, ul, v, left_sum, ur + best_k, v + 1, w, &row_cost);
  if (row_cost <= c0) return false;
  const double c_minus = cost[best_k + search - 1];
  const double c_plus = cost[best_k + search + 1];
  const double curvature = c_minus - 2.0 * c0 + c_plus;
  if (curvature <= 1e-9) return false;
  const double sub = (c_minus - c_plus) / (2.0 * curvature);
  if (std::abs(sub) > 1.0) return false;
  *u_right_px = (ur + best_k + sub) + (u_px - ul);
  return true;
}

}  // namespace deepnav
