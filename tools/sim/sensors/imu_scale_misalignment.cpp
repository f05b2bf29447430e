#include "tools/sim/sensors/imu_scale_misalignment.h"

namespace deepnav::sim {

Eigen::Matrix3d drawScaleMisalignment(double scale_factor_ppm, double misalignment_mrad, NormalRng* rng) {
  Eigen::Matrix3d T = Eigen::Matrix3d::Identity();
  const double scale_sigma = scale_factor_ppm * 1e-6;
  const double misalignment_sigma = misalignment_mrad * 1e-3;
  for (int i = 0; i < 3; ++i) T(i, i) += rng->normal(scale_sigma);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (i != j) T(i, j) = rng->normal(misalignment_sigma);
  return T;
}

}  // namespace deepnav::sim
