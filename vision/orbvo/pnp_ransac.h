#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/orbvo/pose_refiner.h"
#include "vision/orbvo/stereo_rig.h"

namespace deepnav {

struct PnpRansacConfig {
  int iterations = 100;          // RANSAC hypotheses, >= 1
  double reprojection_px = 3.0;  // inlier gate of the left reprojection error, px
  double confidence = 0.99;      // early-exit confidence of cv::solvePnPRansac, (0, 1)
  int min_inliers = 10;          // fewer: no pose
};

// 2D-3D correspondences collected one by one, then a camera pose by RANSAC over minimal AP3P
// solutions (Ke & Roumeliotis, CVPR 2017) with cv::solvePnPRansac, which re-fits the inliers with
// EPnP. The pose is only a starting point for refineCameraPose. The correspondence buffers are
// sized in init(); OpenCV allocates inside solvePnPRansac.
class PnpRansac {
 public:
  bool init(int max_correspondences);
  void clear();
  // False when the buffers are full.
  bool add(const Eigen::Vector3d& p_in_world_m, const Eigen::Vector2d& uv_px);
  int size() const { return static_cast<int>(object_points_.size()); }

  // Pose of the left camera; inlier[i] (size() entries) marks correspondence i. False without a
  // pose of at least min_inliers inliers.
  bool solve(const StereoRig& rig, const PnpRansacConfig& config, CameraPoseEstimate* pose,
             std::uint8_t* inlier);

 private:
  int capacity_ = 0;
  std::vector<cv::Point3f> object_points_;
  std::vector<cv::Point2f> image_points_;
  std::vector<int> inlier_indices_;
};

}  // namespace deepnav
