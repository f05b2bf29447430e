#include "vision/orbvo/grid_orb_extractor.h"

#include <algorithm>
#include <cmath>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

namespace deepnav {
namespace {

bool validConfig(const OrbExtractorConfig& c) {
  return c.grid_cols >= 1 && c.grid_cols <= 64 && c.grid_rows >= 1 && c.grid_rows <= 64 &&
         c.max_features_per_cell >= 1 && c.n_levels >= 1 && c.n_levels <= 8 &&
         c.scale_factor > 1.0 && c.scale_factor <= 2.0 && c.fast_threshold_max >= 1 &&
         c.fast_threshold_max <= 255 && c.fast_threshold_min >= 1 &&
         c.fast_threshold_min <= c.fast_threshold_max && c.fast_contrast_gain > 0.0 &&
         c.smoothing_sigma_px > 0.0 &&
         (c.smoothing_kernel_px == 0 ||
          (c.smoothing_kernel_px % 2 == 1 && c.smoothing_kernel_px >= 3 && c.smoothing_kernel_px <= 21));
}

}  // namespace

bool GridOrbExtractor::init(const OrbExtractorConfig& config, int width_px, int height_px) {
  if (!validConfig(config)) return false;
  const int min_side = 2 * SteeredBrief::kBorderPx + 8;
  if (width_px < min_side || height_px < min_side) return false;
  config_ = config;
  width_px_ = width_px;
  height_px_ = height_px;
  levels_.assign(config.n_levels, cv::Mat());
  smoothed_.assign(config.n_levels, cv::Mat());
  brief_offsets_.assign(config.n_levels, SteeredBrief::Offsets());
  scales_.assign(config.n_levels, 1.0);
  cell_budget_.assign(config.n_levels, 0);
  capacity_ = 0;
  for (int l = 0; l < config.n_levels; ++l) {
    scales_[l] = std::pow(config.scale_factor, l);
    const int w = static_cast<int>(std::lround(width_px / scales_[l]));
    const int h = static_cast<int>(std::lround(height_px / scales_[l]));
    if (w < min_side || h < min_side) return false;
    if (l > 0) levels_[l].create(h, w, CV_8UC1);
    smoothed_[l].create(h, w, CV_8UC1);
    brief_.fillOffsets(static_cast<int>(smoothed_[l].step1()), &brief_offsets_[l]);
    cell_budget_[l] = std::max(
        1, static_cast<int>(std::lround(config.max_features_per_cell / (scales_[l] * scales_[l]))));
    capacity_ += cell_budget_[l] * config.grid_cols * config.grid_rows;
  }
  std::vector<cv::Size> level_sizes;
  for (const cv::Mat& s : smoothed_) level_sizes.push_back(s.size());
  exact_blur_ = blur_.init(config.smoothing_sigma_px, config.smoothing_kernel_px, level_sizes);
  corner_map_fast_ = false;
  if (config.fast_corner_map) {
    corner_map_.init(width_px, height_px);
    corner_map_fast_ = corner_map_.exact();
  }
  cell_threshold_.assign(
      static_cast<std::size_t>(config.n_levels) * config.grid_cols * config.grid_rows, 0);
  x_edges_.assign(config.grid_cols + 1, 0);
  first_threshold_.assign(config.grid_cols, 0);
  fast_corners_.reserve(static_cast<std::size_t>(width_px) * height_px / 16 + 64);
  cell_corners_.reserve(fast_corners_.capacity());
  return true;
}

int GridOrbExtractor::extract(const cv::Mat& grey, std::vector<OrbFeature>* features,
                              std::vector<OrbDescriptor>* descriptors) {
  features->clear();
  descriptors->clear();
  if (grey.type() != CV_8UC1 || grey.cols != width_px_ || grey.rows != height_px_) return -1;
  levels_[0] = grey;  // a header: level 0 is the caller's image
  for (int l = 1; l < config_.n_levels; ++l) {
    cv::resize(levels_[l - 1], levels_[l], levels_[l].size(), 0.0, 0.0, cv::INTER_LINEAR);
  }
  for (int l = 0; l < config_.n_levels; ++l) extractLevel(l, features, descriptors);
  levels_[0] = cv::Mat();
  return static_cast<int>(features->size());
}

void GridOrbExtractor::extractLevel(int level, std::vector<OrbFeature>* features,
                                    std::vector<OrbDescriptor>* descriptors) {
  const cv::Mat& image = levels_[level];
  if (exact_blur_ && !image.isSubmatrix()) {
    blur_.apply(image, &smoothed_[level]);  // the same bits as cv::GaussianBlur, checked in init()
  } else {
    const cv::Size kernel(config_.smoothing_kernel_px, config_.smoothing_kernel_px);
    cv::GaussianBlur(image, smoothed_[level], kernel, config_.smoothing_sigma_px);
  }
  SteeredBrief::Offsets& offsets = brief_offsets_[level];
  const int smoothed_step = static_cast<int>(smoothed_[level].step1());
  if (offsets.step != smoothed_step) brief_.fillOffsets(smoothed_step, &offsets);
  const int border = SteeredBrief::kBorderPx;
  const int usable_w = image.cols - 2 * border;
  const int usable_h = image.rows - 2 * border;
  const double scale = scales_[level];
  for (int gx = 0; gx <= config_.grid_cols; ++gx) x_edges_[gx] = border + usable_w * gx / config_.grid_cols;
  for (int gy = 0; gy < config_.grid_rows; ++gy) {
    const int y0 = border + usable_h * gy / config_.grid_rows;
    const int y1 = border + usable_h * (gy + 1) / config_.grid_rows;
    int* thresholds = &cell_threshold_[(level * config_.grid_rows + gy) * config_.grid_cols];
    for (int gx = 0; gx < config_.grid_cols; ++gx) {
      const cv::Rect cell(x_edges_[gx], y0, x_edges_[gx + 1] - x_edges_[gx], y1 - y0);
      first_threshold_[gx] = firstThreshold(image, cell, &thresholds[gx]);
    }
    if (corner_map_fast_) {  // the row's first FAST pass in one go
      corner_map_.computeCells(image, y0, y1, x_edges_.data(), first_threshold_.data(), config_.grid_cols);
    }
    for (int gx = 0; gx < config_.grid_cols; ++gx) {
      const cv::Rect cell(x_edges_[gx], y0, x_edges_[gx + 1] - x_edges_[gx], y1 - y0);
      detectCell(image, cell, cell_budget_[level], first_threshold_[gx], &thresholds[gx]);
      for (const cv::KeyPoint& kp : cell_corners_) {
        const int x = static_cast<int>(kp.pt.x);
        const int y = static_cast<int>(kp.pt.y);
        OrbFeature f;
        f.angle_rad = brief_.orientationRad(image, x, y);
        // Centre of level pixel x in level-0 pixels, for cv::resize's pixel-area alignment.
        f.u_px = static_cast<float>((x + 0.5) * scale - 0.5);
        f.v_px = static_cast<float>((y + 0.5) * scale - 0.5);
        f.response = kp.response;
        f.level = level;
        features->push_back(f);
        descriptors->emplace_back();
        brief_.describe(smoothed_[level], offsets, x, y, f.angle_rad, &descriptors->back());
      }
    }
  }
}

// The cell's FAST threshold for its first pass: its own, set from its contrast on the first image.
int GridOrbExtractor::firstThreshold(const cv::Mat& image, const cv::Rect& cell, int* cell_threshold) const {
  if (*cell_threshold == 0) {
    cv::Scalar mean, stddev;
    cv::meanStdDev(image(cell), mean, stddev);
    *cell_threshold =
        std::max(1, static_cast<int>(std::lround(config_.fast_contrast_gain * stddev[0])));
  }
  return std::clamp(*cell_threshold, config_.fast_threshold_min, config_.fast_threshold_max);
}

// Leaves in cell_corners_ the `budget` strongest corners inside `cell` (level coordinates), searched
// first at `first_threshold` (firstThreshold()); with the corner map, the strengths of that pass are
// already computed (extractLevel).
void GridOrbExtractor::detectCell(const cv::Mat& image, const cv::Rect& cell, int budget, int first_threshold,
                                  int* cell_threshold) {
  cell_corners_.clear();
  // FAST cannot fire within 3 px of its image's edge: widen the ROI so the whole cell is searched.
  constexpr int r = FastCornerMap::kRadiusPx;
  const cv::Rect roi(cell.x - r, cell.y - r, cell.width + 2 * r, cell.height + 2 * r);
  int threshold = first_threshold;
  bool first_pass = true;
  for (;;) {
    if (corner_map_fast_) {
      if (!first_pass) corner_map_.compute(image, cell, threshold);
      corner_map_.detect(cell, threshold, &cell_corners_);
    } else {
      cv::FAST(image(roi), fast_corners_, threshold, true, cv::FastFeatureDetector::TYPE_9_16);
      cell_corners_.clear();
      for (cv::KeyPoint kp : fast_corners_) {
        kp.pt.x += static_cast<float>(roi.x);
        kp.pt.y += static_cast<float>(roi.y);
        if (cell.contains(cv::Point(static_cast<int>(kp.pt.x), static_cast<int>(kp.pt.y)))) {
          cell_corners_.push_back(kp);
        }
      }
    }
    if (first_pass) {
      const int found = static_cast<int>(cell_corners_.size());
      const int step = std::max(1, threshold / 8);
      if (found > 4 * budget)
        *cell_threshold = std::min(threshold + step, config_.fast_threshold_max);
      if (found < 2 * budget)
        *cell_threshold = std::max(threshold - step, config_.fast_threshold_min);
      first_pass = false;
    }
    if (2 * static_cast<int>(cell_corners_.size()) >= budget ||
        threshold <= config_.fast_threshold_min)
      break;
    threshold = config_.fast_threshold_min;
  }
  if (static_cast<int>(cell_corners_.size()) > budget) {
    std::nth_element(
        cell_corners_.begin(), cell_corners_.begin() + budget, cell_corners_.end(),
        [](const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.response > b.response; });
    cell_corners_.resize(budget);
  }
}

}  // namespace deepnav
