#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "drivers/foreign/topic_map.h"

// NED/FRD to ENU/FLU at the input boundary. Both are right-handed, so each is one proper rotation:
//   body:  v_flu = R_flu_frd v_frd, R_flu_frd = diag(1, -1, -1)   (a half turn about x: y and z flip)
//   world: v_enu = R_enu_ned v_ned, R_enu_ned = [[0, 1, 0], [1, 0, 0], [0, 0, -1]]   (x <-> y, z flips)
// A body vector (rate, specific force, velocity, magnetic field) takes R_flu_frd. An orientation
// q_ned_frd (body FRD -> world NED, as sensor_msgs/Imu gives sensor -> world) becomes
//   q_enu_flu = R_enu_ned * q_ned_frd * R_frd_flu   (R_frd_flu = R_flu_frd, its own inverse),
// so an FRD body level and facing north (identity in NED) faces north in ENU: yaw +90 deg.
// Covariances transform as R C R^T.
namespace deepnav::foreign {

const Eigen::Matrix3d& rotationFluFromFrd();
const Eigen::Matrix3d& rotationEnuFromNed();

Eigen::Vector3d bodyVectorToFlu(const Eigen::Vector3d& v, FrameConvention convention);
Eigen::Matrix3d bodyCovarianceToFlu(const Eigen::Matrix3d& c, FrameConvention convention);
Eigen::Quaterniond orientationToEnuFlu(const Eigen::Quaterniond& q, FrameConvention convention);

}  // namespace deepnav::foreign
