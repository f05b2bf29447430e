#pragma once
#include <opencv2/core.hpp>
#include <vector>

#include "vision/orbvo/fast_corner_map.h"
#include "vision/orbvo/fixed_point_gaussian.h"
#include "vision/orbvo/orb_feature.h"
#include "vision/orbvo/steered_brief.h"

namespace deepnav {

// Bucketed ORB: each pyramid level is cut into grid_cols x grid_rows cells and each cell keeps its
// strongest FAST-9 corners, so features spread over the image instead of piling up on the most
// contrasted object. Underwater images are often low in contrast and uneven (light cone,
// backscatter), so every cell has its own FAST threshold: on the first image it follows the cell's
// contrast, t = clamp(gain * stddev_cell, t_min, t_max); afterwards it tracks the number of corners
// the cell gives, up by 1/8 when they exceed 4x the budget and down by 1/8 below 2x (FAST's cost
// grows with the number of corners, about 1 ms per 2000 on one core). A cell that yields fewer than
// half its budget is searched again at t_min at once. Keep one extractor per camera: the thresholds
// are its state.
struct OrbExtractorConfig {
  int grid_cols = 8;  // cells across, [1, 64]
  int grid_rows = 6;  // cells down, [1, 64]
  // Level-0 budget per cell; level l keeps max / s^(2l), at least 1
  int max_features_per_cell = 10;
  int n_levels = 3;                 // pyramid levels, [1, 8]
  double scale_factor = 1.2;        // between levels, (1, 2]
  int fast_threshold_max = 40;      // grey levels, [1, 255]
  int fast_threshold_min = 5;       // grey levels, [1, fast_threshold_max]
  double fast_contrast_gain = 0.8;  // first threshold per unit of cell intensity stddev, > 0
  double smoothing_sigma_px = 2.0;  // Gaussian applied before BRIEF sampling (as ORB), > 0
  // Taps of that Gaussian, odd in [3, 21]; 0: OpenCV's choice from the sigma (13 at 2 px)
  int smoothing_kernel_px = 0;
  // Corners from FastCornerMap (the same corners as cv::FAST per cell, checked at init, in fewer
  // instructions); false calls cv::FAST per cell, the reference the tests compare with.
  bool fast_corner_map = true;
};

// Allocation: every image and bookkeeping buffer is sized in init(); in extract() only OpenCV allocates:
// cv::resize (the pyramid, on some builds), cv::meanStdDev (a cell's first image), and cv::FAST and
// cv::GaussianBlur where this OpenCV differs from what FastCornerMap and FixedPointGaussian reproduce.
class GridOrbExtractor {
 public:
  bool init(const OrbExtractorConfig& config, int width_px, int height_px);

  // Upper bound of the number of features of one image.
  int capacity() const { return capacity_; }
  int levels() const { return config_.n_levels; }
  double levelScale(int level) const { return scales_[level]; }
  // True when the smoothing runs in FixedPointGaussian (same bits as cv::GaussianBlur, fewer instructions).
  bool smoothsInFixedPoint() const { return exact_blur_; }
  // True when the corners come from FastCornerMap (same corners as cv::FAST per cell).
  bool detectsWithCornerMap() const { return corner_map_fast_; }

  // Features of `grey` (CV_8UC1 of the init size), sorted by level; descriptors[i] belongs to
  // features[i]. Both vectors are cleared first and never grow past capacity(). Returns the count,
  // -1 for a bad image.
  int extract(const cv::Mat& grey, std::vector<OrbFeature>* features,
              std::vector<OrbDescriptor>* descriptors);

 private:
  void extractLevel(int level, std::vector<OrbFeature>* features,
                    std::vector<OrbDescriptor>* descriptors);
  int firstThreshold(const cv::Mat& image, const cv::Rect& cell, int* cell_threshold) const;
  void detectCell(const cv::Mat& image, const cv::Rect& cell, int budget, int first_threshold,
                  int* cell_threshold);

  OrbExtractorConfig config_{};
  int width_px_ = 0;
  int height_px_ = 0;
  int capacity_ = 0;
  std::vector<cv::Mat> levels_;
  std::vector<cv::Mat> smoothed_;
  std::vector<SteeredBrief::Offsets> brief_offsets_;  // per level, for smoothed_[level]'s step
  std::vector<double> scales_;
  std::vector<int> cell_budget_;
  std::vector<int> cell_threshold_;         // per level and cell; 0 until the first image
  std::vector<int> x_edges_;                // the grid's column edges on the current level
  std::vector<int> first_threshold_;        // the first-pass thresholds of the current row of cells
  std::vector<cv::KeyPoint> fast_corners_;  // one FAST call
  std::vector<cv::KeyPoint> cell_corners_;  // the corners of one cell
  SteeredBrief brief_;
  FixedPointGaussian blur_;  // cv::GaussianBlur's result in about 60 % of its instructions
  bool exact_blur_ = false;  // blur_ reproduces cv::GaussianBlur for every level
  FastCornerMap corner_map_;      // FAST strength of the current row of cells
  bool corner_map_fast_ = false;  // corner_map_ reproduces cv::FAST and the config asks for it
};

}  // namespace deepnav
