#pragma once

namespace deepnav {

// Geometry of a rectified stereo pair, left camera as reference (optical frame C: x right, y down,
// z forward). A left pixel (u, v) with disparity d (px) is the point
//   Z = fx * B / d,  X = (u - cx) * Z / fx,  Y = (v - cy) * Z / fy.
// Pixel centres sit at integer coordinates.
struct StereoGeometry {
  double fx_px = 700.0;
  double fy_px = 700.0;
  double cx_px = 343.5;
  double cy_px = 257.5;
  double baseline_m = 0.12;

  // f * B (px m): Z = focalBaseline() / d.
  double focalBaseline() const { return fx_px * baseline_m; }
  bool isValid() const { return fx_px > 0.0 && fy_px > 0.0 && baseline_m > 0.0; }
};

}  // namespace deepnav
