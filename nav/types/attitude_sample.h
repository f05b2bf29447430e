#pragma once
#include "nav/types/time.h"

namespace deepnav {

// Roll and pitch of the robot from an AHRS, ENU/FLU convention (REP-103), radians.
struct AttitudeSample {
  TimeUs t_us = 0;
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
  double sigma_rad = 0.0;  // 1-sigma; 0 means "use the configured default"
};

}  // namespace deepnav
