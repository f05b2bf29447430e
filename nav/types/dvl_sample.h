#pragma once
#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "nav/types/time.h"

namespace deepnav {

// DVL bottom-track ensemble: velocity of the DVL over the seabed, in the DVL frame (FLU as mounted).
struct DvlSample {
  static constexpr int kBeams = 4;
  TimeUs t_us = 0;
  Eigen::Vector3d v_dvl_mps = Eigen::Vector3d::Zero();  // velocity of the DVL w.r.t. the bottom
  std::array<double, kBeams> beam_range_m{};            // slant range of each beam to the bottom
  std::uint8_t beam_valid_mask = 0;                     // bit i set when beam i locked on the bottom
  bool valid = false;                                    // velocity usable (>= 3 beams, instrument OK)
  double fom_mps = 0.0;                                  // figure of merit (1-sigma speed error)
  Eigen::Matrix3d cov_v_dvl_mps2 = Eigen::Matrix3d::Zero();  // velocity covariance, DVL frame
  double altitude_m = 0.0;                               // mean vertical range to the bottom
};

}  // namespace deepnav
