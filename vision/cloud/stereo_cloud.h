#pragma once
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "vision/cloud/cloud_from_disparity.h"
#include "vision/cloud/mixed_pixel_filter.h"
#include "vision/cloud/organized_cloud.h"
#include "vision/cloud/stereo_geometry.h"
#include "vision/stereo/disparity_estimator.h"

namespace deepnav {

enum class DenseStereoMethod { kElas, kSgbm, kSgbmWls };

// Dense stereo -> organised cloud of one rectified pair, for the stage-1 workspace map and the plane VO.
struct StereoCloudConfig {
  DenseStereoMethod method = DenseStereoMethod::kElas;
  // The images are reduced by this factor before matching (1 or 2). With the DexROV rig
  // (f B = 700 px * 0.30 m) the panel at 1.5 m sits at 140 px of disparity; at half size 70 px,
  // and 128 disparities cover down to 0.82 m (the faces come to 0.9 m of the camera) at a quarter of
  // the matching cost.
  int scale_down = 2;
  int num_disparities = 128;  // at the reduced size
  int cloud_step_px = 1;     // at the reduced size
  int channels = 1;          // of the camera images (1 grey, 3 BGR)
  CloudConfig cloud;
  MixedPixelConfig mixed;
};

// Owns the backend and every buffer (sized in init(); compute() allocates nothing of its own).
class StereoCloud {
 public:
  StereoCloud();
  ~StereoCloud();
  StereoCloud(const StereoCloud&) = delete;
  StereoCloud& operator=(const StereoCloud&) = delete;

  // geometry: of the full-size rectified pair. False with *error naming the field.
  bool init(const StereoCloudConfig& config, const StereoGeometry& geometry, int width_px, int height_px,
            std::string* error);

  // Disparity, cloud (left camera optical frame) and mixed-pixel removal. False on a size mismatch.
  bool compute(const cv::Mat& left, const cv::Mat& right, OrganizedCloud* cloud);
  // Same from a disparity map of the reduced size (the simulator's truth, the `gt` backend).
  bool computeFromDisparity(const cv::Mat& disparity_px, OrganizedCloud* cloud);

  bool allocateCloud(OrganizedCloud* cloud) const { return builder_.allocateCloud(cloud); }
  const StereoGeometry& geometry() const { return builder_.geometry(); }  // of the reduced images
  const cv::Mat& disparity() const { return disparity_px_; }             // of the last compute()
  int rows() const { return builder_.gridRows(); }
  int cols() const { return builder_.gridCols(); }
  int stepPx() const { return config_.cloud_step_px * config_.scale_down; }  // in full-size pixels

 private:
  bool reduce(const cv::Mat& full, cv::Mat* reduced) const;

  StereoCloudConfig config_;
  std::unique_ptr<DisparityEstimator> backend_;
  CloudFromDisparity builder_;
  MixedPixelFilter mixed_;
  cv::Mat left_small_, right_small_, disparity_px_;
  int width_px_ = 0;
  int height_px_ = 0;
};

}  // namespace deepnav
