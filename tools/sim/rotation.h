#pragma once
#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav::sim {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// Rotation from roll, pitch, yaw in degrees, ZYX convention (R = Rz(yaw) Ry(pitch) Rx(roll)) as in REP-103.
// Mounting rotations in scenario files use it: R_robot_sensor = rotationFromRpyDeg(mount_rpy_deg).
inline Eigen::Matrix3d rotationFromRpyDeg(const std::array<double, 3>& rpy_deg) {
  return (Eigen::AngleAxisd(rpy_deg[2] * kDegToRad, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy_deg[1] * kDegToRad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy_deg[0] * kDegToRad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

inline Eigen::Vector3d toVector(const std::array<double, 3>& a) { return {a[0], a[1], a[2]}; }

// Angle in [0, 2*pi).
inline double wrapTo2Pi(double a_rad) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double w = std::fmod(a_rad, kTwoPi);
  if (w < 0.0) w += kTwoPi;
  return w >= kTwoPi ? 0.0 : w;
}

// Angle in [-pi, pi).
inline double wrapToPi(double a_rad) { return wrapTo2Pi(a_rad + std::numbers::pi) - std::numbers::pi; }

}  // namespace deepnav::sim
