#pragma once
#include <Eigen/Core>

#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// The deterministic error of one sensor triad, drawn once per dive: measured = T true with
//   T = I + diag(s_x, s_y, s_z) + M,   s_i ~ N(0, scale_factor_ppm 1e-6),
//   M = off-diagonal only, each m_ij ~ N(0, misalignment_mrad 1e-3)   (i != j),
// m_ij being the sensitivity of axis i to the true axis j (small-angle non-orthogonality and mounting
// misalignment of the sensing axes relative to the IMU case; the case's own mounting is mount_rpy_deg).
// Draw order: s_x, s_y, s_z, then m_xy, m_xz, m_yx, m_yz, m_zx, m_zy.
Eigen::Matrix3d drawScaleMisalignment(double scale_factor_ppm, double misalignment_mrad, NormalRng* rng);

}  // namespace deepnav::sim
