#pragma once
#include <Eigen/Core>

#include "vision/orbvo/stereo_rig.h"

namespace deepnav {

// Stereo projection of a point p_in_cam_m = (x, y, z) of the left camera frame:
//   u = fx x / z + cx,   v = fy y / z + cy,   u_r = fx (x - b) / z + cx
// and its Jacobian with respect to the point. Rows 0..1 are the left pixel, row 2 the right column.
struct StereoProjection {
  Eigen::Vector3d uvr_px;     // (u, v, u_r)
  Eigen::Matrix3d d_uvr_d_p;  // d(u, v, u_r) / d(x, y, z)
};

inline StereoProjection projectStereo(const StereoRig& rig, const Eigen::Vector3d& p_in_cam_m) {
  const double inv_z = 1.0 / p_in_cam_m.z();
  const double x = p_in_cam_m.x();
  const double y = p_in_cam_m.y();
  StereoProjection out;
  out.uvr_px = {rig.fx_px * x * inv_z + rig.cx_px, rig.fy_px * y * inv_z + rig.cy_px,
                rig.fx_px * (x - rig.baseline_m) * inv_z + rig.cx_px};
  out.d_uvr_d_p << rig.fx_px * inv_z, 0.0, -rig.fx_px * x * inv_z * inv_z,  //
      0.0, rig.fy_px * inv_z, -rig.fy_px * y * inv_z * inv_z,               //
      rig.fx_px * inv_z, 0.0, -rig.fx_px * (x - rig.baseline_m) * inv_z * inv_z;
  return out;
}

// Left pixel of a point of the left camera frame (z > 0 assumed).
inline Eigen::Vector2d projectLeft(const StereoRig& rig, const Eigen::Vector3d& p_in_cam_m) {
  return {rig.fx_px * p_in_cam_m.x() / p_in_cam_m.z() + rig.cx_px,
          rig.fy_px * p_in_cam_m.y() / p_in_cam_m.z() + rig.cy_px};
}

}  // namespace deepnav
