#pragma once
#include "nav/types/time.h"

namespace deepnav {

// Compass heading: clockwise from north (NED convention of marine compasses), radians in [0, 2*pi).
// The EKF converts it to an ENU yaw (yaw = pi/2 - heading) after declination and bias correction.
struct HeadingSample {
  TimeUs t_us = 0;
  double heading_rad = 0.0;
  bool is_true = false;        // true north (gyrocompass) rather than magnetic north
  double sigma_rad = 0.0;      // 1-sigma; 0 means "use the configured default"
};

}  // namespace deepnav
