#include "vision/orbvo/pnp_ransac.h"

#include <algorithm>
#include <opencv2/calib3d.hpp>

#include "base/so3.h"

namespace deepnav {

bool PnpRansac::init(int max_correspondences) {
  if (max_correspondences < 4) return false;
  capacity_ = max_correspondences;
  object_points_.reserve(max_correspondences);
  image_points_.reserve(max_correspondences);
  inlier_indices_.reserve(max_correspondences);
  return true;
}

void PnpRansac::clear() {
  object_points_.clear();
  image_points_.clear();
}

bool PnpRansac::add(const Eigen::Vector3d& p_in_world_m, const Eigen::Vector2d& uv_px) {
  if (size() >= capacity_) return false;
  object_points_.emplace_back(static_cast<float>(p_in_world_m.x()),
                              static_cast<float>(p_in_world_m.y()),
                              static_cast<float>(p_in_world_m.z()));
  image_points_.emplace_back(static_cast<float>(uv_px.x()), static_cast<float>(uv_px.y()));
  return true;
}

bool PnpRansac::solve(const StereoRig& rig, const PnpRansacConfig& config, CameraPoseEstimate* pose,
                      std::uint8_t* inlier) {
  const int n = size();
  std::fill_n(inlier, n, std::uint8_t{0});
  if (n < std::max(4, config.min_inliers)) return false;
  const cv::Matx33d K(rig.fx_px, 0.0, rig.cx_px, 0.0, rig.fy_px, rig.cy_px, 0.0, 0.0, 1.0);
  cv::Vec3d rvec, tvec;
  inlier_indices_.clear();
  const bool ok =
      cv::solvePnPRansac(object_points_, image_points_, K, cv::noArray(), rvec, tvec, false,
                         config.iterations, static_cast<float>(config.reprojection_px),
                         config.confidence, inlier_indices_, cv::SOLVEPNP_AP3P);
  if (!ok || static_cast<int>(inlier_indices_.size()) < config.min_inliers) return false;
  const Eigen::Vector3d phi(rvec[0], rvec[1], rvec[2]);
  const Eigen::Vector3d t(tvec[0], tvec[1], tvec[2]);
  if (!phi.allFinite() || !t.allFinite()) return false;
  pose->R_cam_world = expSo3(phi);
  pose->p_world_in_cam_m = t;
  for (int i : inlier_indices_) {
    if (i >= 0 && i < n) inlier[i] = 1;
  }
  pose->inliers = static_cast<int>(inlier_indices_.size());
  return true;
}

}  // namespace deepnav
