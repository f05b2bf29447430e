#pragma once

namespace deepnav {

// Pinhole camera of a rectified image (no distortion), pixel centres at integer coordinates:
//   u = fx * x / z + cx,  v = fy * y / z + cy   for a point (x, y, z) in the optical frame C.
struct PinholeIntrinsics {
  double fx_px = 700.0;
  double fy_px = 700.0;
  double cx_px = 343.5;
  double cy_px = 257.5;
};

}  // namespace deepnav
