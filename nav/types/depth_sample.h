#pragma once
#include "nav/types/time.h"

namespace deepnav {

// Depth from a pressure sensor. depth_m is positive down; the odometry frame's z is up, so z = -depth.
struct DepthSample {
  TimeUs t_us = 0;
  double pressure_pa = 0.0;  // absolute pressure as measured
  double depth_m = 0.0;      // (p - p_atm) / (rho * g), computed by the driver
  double sigma_m = 0.0;      // 1-sigma; 0 means "use the configured default"
};

}  // namespace deepnav
