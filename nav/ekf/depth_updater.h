#pragma once
#include "nav/ekf/filter_state.h"
#include "nav/ekf/measurement_update.h"
#include "nav/types/depth_sample.h"

namespace deepnav {

struct EkfConfig;

bool isValidDepth(const DepthSample& m);

// Depth of the pressure port (positive down, odom z up, r = p_depth_in_robot):
//   h(x) = -(p + R r)_z,   H_p = [0 0 -1],   H_theta = e_z^T [R r]x     (R r ~= R_hat r - [R_hat r]x dtheta)
bool linearizeDepth(const FilterState& s, const DepthSample& m, const EkfConfig& config, Linearization* out);

}  // namespace deepnav
