#pragma once
#include <array>
#include <vector>

#include <Eigen/Core>

#include "tools/sim/sensors/camera_rig.h"

namespace deepnav::sim {

// Motion blur of one view (camera.motion_blur): during the exposure T the scene point seen at pixel p
// moves across the image at the velocity of the static-scene optical flow (Longuet-Higgins and Prazdny,
// Proc. R. Soc. Lond. B 208, 1980) of a camera with linear velocity v and angular rate w (both in its
// optical frame), at normalised coordinates (x, y) and depth Z:
//   dx/dt = (-v_x + x v_z) / Z + x y w_x - (1 + x^2) w_y + y w_z
//   dy/dt = (-v_y + y v_z) / Z + (1 + y^2) w_x - x y w_y - x w_z
// (Z = infinity in open water: rotation only). The pixel integrates the radiance along its motion
// vector d = (fx dx/dt, fy dy/dt) T centred on the mid-exposure instant (the frame's stamp): the mean
// of 2 + floor(|d|) bilinear samples of the sharp image spaced evenly over [-d/2, d/2]. Per-pixel vectors
// from the view's own depth; the motion of the fish and of the arm is not included (static scene), nor
// the change of the flow during the exposure (constant twist). Buffers are sized in init().
class MotionBlur {
 public:
  static constexpr int kMaxSamples = 48;  // blur longer than 47 px is sampled sparsely
  // Shorter blur is left out: under half a pixel it is below the lens blur (the sensor's 3 x 3 [1 2 1]
  // kernel, sigma 0.71 px) and would cost the samples of every pixel of a slow view.
  static constexpr float kMinLength_px = 0.5f;

  // camera: the pinhole the view is rendered with (for a flat port, its helper pinhole: the port image
  // is, to first order, that pinhole's image); channels 1 or 3.
  bool init(const CameraConfig& camera, int channels);
  // radiance: width * height * channels floats, blurred in place; depth_m: width * height (0 = open water).
  void apply(float* radiance, const float* depth_m, const Eigen::Vector3d& v_cam_mps, const Eigen::Vector3d& w_cam_radps,
             float exposure_s);
  // The longest blur vector of the last apply(), px.
  float lastMaxLength_px() const { return last_max_length_px_; }

 private:
  void sample(float u, float v, float* acc) const;

  int width_ = 0, height_ = 0, channels_ = 1;
  float fx_ = 1.0f, fy_ = 1.0f, cx_ = 0.0f, cy_ = 0.0f;
  std::vector<float> sharp_;  // a copy of the input: the samples read the unblurred image
  std::array<float, kMaxSamples + 1> reciprocal_{};  // 1 / k
  std::vector<float> row_du_, row_dv_, row_length2_;  // one row's blur vectors (px) and squared lengths
  float last_max_length_px_ = 0.0f;
};

}  // namespace deepnav::sim
