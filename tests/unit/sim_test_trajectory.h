#pragma once
// Checks shared by the trajectory tests (header-only, test code).
#include <gtest/gtest.h>

#include "tools/sim/trajectory.h"

namespace deepnav::sim::test {

// The analytic velocity and acceleration of `t` against central differences of position and velocity
// (h = 1e-4 s, error ~h^2 * jerk < 1e-8), every step_s from 0 to end_s, joints included. A level trajectory
// (no roll, no pitch: its body z rate is the yaw rate) has its yaw rate checked the same way.
inline void expectDerivativesOfPosition(const Trajectory& t, double end_s, double step_s, bool level) {
  const double h = 1e-4;
  for (double time = 0.0; time <= end_s; time += step_s) {
    const KinematicState s = t.stateAt(time);
    const KinematicState before = t.stateAt(time - h), after = t.stateAt(time + h);
    const Eigen::Vector3d v_numeric = (after.p_robot_in_odom_m - before.p_robot_in_odom_m) / (2 * h);
    const Eigen::Vector3d a_numeric = (after.v_robot_in_odom_mps - before.v_robot_in_odom_mps) / (2 * h);
    EXPECT_LT((v_numeric - s.v_robot_in_odom_mps).norm(), 1e-6) << "t = " << time;
    EXPECT_LT((a_numeric - s.a_robot_in_odom_mps2).norm(), 1e-6) << "t = " << time;
    if (level) {
      EXPECT_NEAR((after.yaw_rad - before.yaw_rad) / (2 * h), s.w_robot_radps.z(), 1e-6) << "t = " << time;
    }
  }
}

}  // namespace deepnav::sim::test
