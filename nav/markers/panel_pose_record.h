#pragma once
#include <array>
#include <cstdint>

namespace deepnav {

// A fixed panel pose as plain numbers, to be saved by board/ and restored on a restart (so that the
// vehicle can start directly in stage 2). Matrices are row-major 3x3.
struct PanelPoseRecord {
  std::array<double, 3> p_panel_in_odom_m{};
  std::array<double, 4> q_odom_panel_xyzw{0.0, 0.0, 0.0, 1.0};
  std::array<double, 9> cov_position_m2{};  // covariance of the mean position
  std::array<double, 9>
      cov_rotation_rad2{};        // covariance of the mean rotation, about the odom axes
  std::int32_t observations = 0;  // accepted observations averaged
  std::int32_t distinct_markers = 0;
  std::int64_t t_fixed_us = 0;  // time of the observation that fixed it
};

}  // namespace deepnav
