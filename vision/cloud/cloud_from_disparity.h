#pragma once
#include <opencv2/core.hpp>
#include <vector>

#include "vision/cloud/organized_cloud.h"
#include "vision/cloud/stereo_geometry.h"

namespace deepnav {

// Which disparities become points.
struct CloudConfig {
  double min_range_m = 0.3;  // Z below this is dropped (too close for the rig; range (0, max))
  double max_range_m = 6.0;  // Z above this is dropped: turbid water, disparity noise ~ Z^2
  int step_px = 1;           // sample every step-th pixel in u and v (1 = full resolution)
};

// Turns a dense disparity map (CV_32FC1, px; invalid < 0, vision/stereo) into an organised cloud
// in the left camera frame. The per-column and per-row ray factors (u - cx) / fx, (v - cy) / fy are
// tabulated in init(), so compute() costs one division per point and never allocates.
class CloudFromDisparity {
 public:
  // Returns false for an invalid geometry or config, or an image smaller than one step.
  bool init(const StereoGeometry& geometry, const CloudConfig& config, int width_px, int height_px);

  // disparity_px: width x height CV_32FC1. cloud: allocated by allocateCloud() (or of the grid
  // size). Points with d <= 0 or Z outside [min_range, max_range] are invalid.
  bool compute(const cv::Mat& disparity_px, OrganizedCloud* cloud) const;

  // Sizes a cloud for this grid (start-up).
  bool allocateCloud(OrganizedCloud* cloud) const;

  int gridRows() const { return static_cast<int>(y_per_z_.size()); }
  int gridCols() const { return static_cast<int>(x_per_z_.size()); }
  const StereoGeometry& geometry() const { return geometry_; }
  const CloudConfig& config() const { return config_; }

 private:
  bool ready_ = false;
  StereoGeometry geometry_;
  CloudConfig config_;
  int width_px_ = 0;
  int height_px_ = 0;
  std::vector<float> x_per_z_;  // (u - cx) / fx per grid column
  std::vector<float> y_per_z_;  // (v - cy) / fy per grid row
};

}  // namespace deepnav
