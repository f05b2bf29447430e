#pragma once
#include <Eigen/Core>

#include "nav/ekf/ekf.h"

namespace deepnav::testing {

// One IMU sample of a robot at rest and level (specific force straight up, no rotation), stamped t_us:
// it propagates the filter and fuses the measurements queued before it.
inline void feedRestingImu(TimeUs t_us, Ekf* ekf) {
  ImuSample imu;
  imu.t_us = t_us;
  imu.f_imu_mps2 = Eigen::Vector3d(0.0, 0.0, 9.80665);
  ekf->setImu(imu);
}

}  // namespace deepnav::testing
