#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "vision/orbvo/stereo_rig.h"

namespace deepnav {

// A flat textured rectangle of the world W: texture pixel (s, t) (s along columns, t along rows)
// lies at
//   p = p_origin_in_world_m + texel_m (s axis_s_in_world + t axis_t_in_world).
struct TexturedPlane {
  Eigen::Vector3d p_origin_in_world_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis_s_in_world = Eigen::Vector3d::UnitX();  // unit
  Eigen::Vector3d axis_t_in_world = Eigen::Vector3d::UnitY();  // unit, orthogonal to axis_s
  double texel_m = 0.002;
  cv::Mat texture;  // CV_8UC1
};

// Grey texture of blurred noise at several scales plus random discs and boxes (corners for FAST),
// mean 128 and standard deviation about 45 * contrast. Same seed, same texture.
cv::Mat makeSyntheticTexture(int width_px, int height_px, std::uint64_t seed, double contrast);

// Test and benchmark scene for the stereo odometries: planes rendered into a rectified stereo rig
// by the exact texture-to-image homography u ~ K [R a_s texel, R a_t texel, R o + t] (s, t, 1)^T of
// each camera, painted far to near. Every plane must stay in front
// of the cameras. Not for the steady state: render() allocates (cv::warpPerspective).
class SyntheticPlaneScene {
 public:
  void addPlane(const TexturedPlane& plane) { planes_.push_back(plane); }
  int planeCount() const { return static_cast<int>(planes_.size()); }

  // Left and right images (CV_8UC1, rig size) seen by the left camera at p_cam_in_world_m with
  // orientation q_world_cam (camera optical frame C: x right, y down, z forward); pixels no plane
  // covers keep `background`.
  void render(const StereoRig& rig, const Eigen::Quaterniond& q_world_cam,
              const Eigen::Vector3d& p_cam_in_world_m, std::uint8_t background, cv::Mat* left,
              cv::Mat* right) const;

 private:
  void renderView(const StereoRig& rig, const Eigen::Matrix3d& R_cam_world,
                  const Eigen::Vector3d& p_world_in_cam_m, std::uint8_t background,
                  cv::Mat* image) const;

  std::vector<TexturedPlane> planes_;
};

// The scene of the ORB odometry tests and benchmark, in the frame of a camera at the origin looking
// along +z (x right, y down): a back wall at 3 m (5 x 4 m), a floor rising from 1 m to 2.9 m ahead,
// a 0.9 x 0.7 m panel at 1.5 m turned 30 deg about the vertical, and a 0.5 m box face at 1.1 m.
// Texture contrast as in makeSyntheticTexture; seeds derive from `seed`. The camera may move about
// +-0.5 m.
SyntheticPlaneScene makeOrbVoTestScene(std::uint64_t seed, double contrast);

// The left image of makeOrbVoTestScene(scene_seed, contrast) from the origin on a grey 90 background,
// with Gaussian sensor noise of 1.5 grey levels drawn from noise_seed: the extractor tests' input.
cv::Mat renderOrbVoTestImage(std::uint64_t scene_seed, double contrast, std::uint64_t noise_seed);

}  // namespace deepnav
