#pragma once
#include <Eigen/Core>

namespace deepnav {

// A rectified stereo rig. Both cameras share the intrinsics (no distortion, pixel centres at
// integer coordinates); the right camera sits baseline_m along +x of the left optical frame C (x
// right, y down, z forward), so a point at depth z appears at u_right = u_left - d with disparity d
// = fx b / z.
struct StereoRig {
  double fx_px = 700.0;
  double fy_px = 700.0;
  double cx_px = 343.5;
  double cy_px = 257.5;
  double baseline_m = 0.30;  // > 0
  int width_px = 688;
  int height_px = 516;
};

// Point in the left camera frame from a left pixel and its disparity (inverse of the projection
// above).
inline Eigen::Vector3d triangulateStereo(const StereoRig& rig, double u_px, double v_px,
                                         double disparity_px) {
  const double z_m = rig.fx_px * rig.baseline_m / disparity_px;
  return {(u_px - rig.cx_px) * z_m / rig.fx_px, (v_px - rig.cy_px) * z_m / rig.fy_px, z_m};
}

}  // namespace deepnav
