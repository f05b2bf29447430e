#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/cloud/stereo_geometry.h"

namespace deepnav {

// A textured planar rectangle: centre + s * axis_u + t * axis_v, |s| <= half_u, |t| <= half_v.
struct SyntheticRectangle {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_u = Eigen::Vector3d::UnitX();  // unit, orthogonal to axis_v
  Eigen::Vector3d axis_v = Eigen::Vector3d::UnitY();
  double half_u_m = 1.0;
  double half_v_m = 1.0;
  std::uint32_t texture_seed = 1;

  Eigen::Vector3d normal() const { return axis_u.cross(axis_v).normalized(); }
};

// A textured sphere (a fish, a blob).
struct SyntheticSphere {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  double radius_m = 0.1;
  std::uint32_t texture_seed = 7;
};

// Scenes for tests and benchmarks of the plane pipeline, in a world frame of the caller's choice.
struct SyntheticScene {
  std::vector<SyntheticRectangle> rectangles;
  std::vector<SyntheticSphere> spheres;

  // The six faces of an axis-aligned box (before rotation by yaw about world z) of size
  // (sx, sy, sz) whose bottom face centre is `base`.
  void addBox(const Eigen::Vector3d& base_m, const Eigen::Vector3d& size_m, double yaw_rad,
              std::uint32_t seed);
};

// A pinhole stereo geometry with square pixels of focal f_px, the principal point at the centre of a
// width x height image.
inline StereoGeometry centredStereoGeometry(double f_px, int width_px, int height_px, double baseline_m) {
  StereoGeometry g;
  g.fx_px = g.fy_px = f_px;
  g.cx_px = 0.5 * (width_px - 1);
  g.cy_px = 0.5 * (height_px - 1);
  g.baseline_m = baseline_m;
  return g;
}

// T_world_cam of a camera at position_m (world z up) looking along world +y, pitched down by pitch_down_rad;
// optical axes x right, y down, z forward.
inline Eigen::Isometry3d cameraPitchedDown(double pitch_down_rad, const Eigen::Vector3d& position_m) {
  const Eigen::Vector3d z(0.0, std::cos(pitch_down_rad), -std::sin(pitch_down_rad));
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << x, z.cross(x), z;
  T.translation() = position_m;
  return T;
}

// What a pinhole camera at T_world_cam sees: per pixel, the disparity (px; kInvalidDisparity
// where the ray hits nothing), the index of the surface (rectangles first, then spheres; -1 none),
// and optionally a grey image of a low-contrast procedural texture fixed to the surfaces.
struct SyntheticView {
  cv::Mat disparity_px;  // CV_32FC1
  cv::Mat surface;       // CV_32SC1
  cv::Mat image;         // CV_8UC1 (only when rendered with an image)
};

// Ray casting, no allocation when the view's buffers already have the size.
void renderSyntheticView(const SyntheticScene& scene, const StereoGeometry& geometry, int width_px,
                         int height_px, const Eigen::Isometry3d& T_world_cam, bool with_image,
                         SyntheticView* view);

// A rectified stereo pair of the scene: the left camera at T_world_cam, the right one baseline_m
// along its x axis. `left` also holds the true left disparity.
void renderSyntheticStereoPair(const SyntheticScene& scene, const StereoGeometry& geometry,
                               int width_px, int height_px, const Eigen::Isometry3d& T_world_cam,
                               SyntheticView* left, SyntheticView* right);

}  // namespace deepnav
