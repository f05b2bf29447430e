#pragma once
// Small statistics helpers shared by the simulator tests (header-only, test code).
#include <cmath>
#include <vector>

#include <Eigen/Geometry>

#include "tools/sim/kinematic_state.h"

namespace deepnav::sim::test {

inline double mean(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

inline double stddev(const std::vector<double>& x) {
  const double m = mean(x);
  double sum = 0.0;
  for (double v : x) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(x.size() - 1));
}

// Robot at rest, level, facing east, `height_m` above the odometry origin.
inline KinematicState restingState(double height_m = 1.5, double gravity_mps2 = 9.80665) {
  KinematicState s;
  s.p_robot_in_odom_m = {0.0, 0.0, height_m};
  s.f_robot_mps2 = {0.0, 0.0, gravity_mps2};
  return s;
}

// The same, turned to yaw_rad about z (REP-103: 0 east, counter-clockwise).
inline KinematicState restingStateYawed(double yaw_rad) {
  KinematicState s = restingState();
  s.yaw_rad = yaw_rad;
  s.q_odom_robot = Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ());
  return s;
}

}  // namespace deepnav::sim::test
