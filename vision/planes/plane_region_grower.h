#pragma once
#include <array>
#include <bitset>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/cloud/organized_cloud.h"
#include "vision/planes/plane_extraction_config.h"
#include "vision/planes/scatter_sums.h"

namespace deepnav {

// One grown region: its cells are members()[member_begin, member_begin + member_count), each a
// cell index row * cols + col; in the label grid they hold `label`.
struct PlaneRegion {
  int member_begin = 0;
  int member_count = 0;
  std::uint8_t label = 0;
  ScatterSums sums;                                   // unweighted moments
  double sum_z2 = 0.0;                                // sum of Z^2 (noise scatter, see below)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // least-squares normal, noise-corrected
};

// Region growing of Poppinga et al. (IROS 2008) on an organised cloud: seeds are planar k x k
// patches on a regular grid, tried flattest first; a region grows breadth-first over 4-neighbours;
// a candidate joins when (1) its distance to the region's plane is small and (2) the region's mean
// squared error with it stays small; the moments are updated incrementally. Two changes for
// speed and for stereo: the normal is refitted only when the region has grown by a factor
// (between fits, distance and MSE are O(1) running sums along the fixed normal:
// MSE = (sum a^2 - (sum a)^2 / N) / N with a = n . (p - origin)), and both thresholds grow with
// the depth noise sigma_Z = Z^2 sigma_d / (f B). A region smaller than the minimum releases its
// cells. A third test, on the local surface normal, keeps regions from leaking along the line
// where their plane cuts another surface. All buffers are sized in init().
class PlaneRegionGrower {
 public:
  // fx_px, focal_baseline_pxm = fx * B: the stereo rig; rows, cols, step_px: the cloud grid.
  bool init(const PlaneExtractionConfig& config, double fx_px, double focal_baseline_pxm, int rows,
            int cols, int step_px);
  // Grows the regions of *cloud; returns their number (-1 if the cloud does not match init()).
  int grow(const OrganizedCloud& cloud);

  const cv::Mat& labels() const { return labels_; }  // CV_8UC1: 0 = no plane
  const PlaneRegion& region(int i) const { return regions_[i]; }
  const std::int32_t* members() const { return members_.data(); }
  int seedsTried() const { return seeds_tried_; }
  // Cells admitted over all attempts of the last grow(), kept or released (the work done).
  long cellsAdmitted() const { return cells_admitted_; }
  // Labels whose cells touch label l's cells (4-neighbourhood).
  const std::bitset<256>& adjacentLabels(std::uint8_t l) const { return adjacent_[l]; }

 private:
  struct Seed {
    float mse;
    std::int32_t cell;
  };
  int collectSeeds(const OrganizedCloud& cloud);
  bool patchIsFree(const OrganizedCloud& cloud, int cell) const;
  bool growRegion(const OrganizedCloud& cloud, int seed_cell, std::uint8_t label,
                  PlaneRegion* region);
  void releaseRegion(const PlaneRegion& region);
  Eigen::Matrix3d noiseScatter(const ScatterSums& sums, double sum_z2) const;
  std::uint8_t nextAttempt();

  PlaneExtractionConfig config_;
  float noise_per_z2_ = 0.0f;         // sigma_Z / Z^2 = sigma_d / (f B)
  float normal_span_cells_m_ = 1.0f;  // offset k of the local normal = this / Z (cells * m)
  float cos2_normal_ = 0.0f;
  int rows_ = 0;
  int cols_ = 0;
  int min_cells_ = 0;
  int seed_step_cells_ = 1;
  int half_window_ = 2;
  cv::Mat labels_;
  std::vector<std::uint8_t> stamp_;  // attempt that last examined a cell
  std::uint8_t attempt_ = 0;
  std::vector<std::int32_t> members_;  // also the breadth-first queue
  int member_end_ = 0;
  std::vector<Seed> seeds_;
  std::vector<PlaneRegion> regions_;
  int region_count_ = 0;
  int seeds_tried_ = 0;
  long cells_admitted_ = 0;
  std::array<std::bitset<256>, 256> adjacent_{};
};

}  // namespace deepnav
