#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace deepnav {

// Small rotation-group helpers shared by the error-state filter (nav) and visual odometry (vision).
// Conventions (Sola, "A micro Lie theory for state estimation in robotics", 2018): Exp/Log map between
// so(3) vectors and rotation matrices;
// Jr is the right Jacobian, Exp(phi + d) ~= Exp(phi) Exp(Jr(phi) d)  (Sola eq. 143);
// Jl is the left Jacobian,  Exp(phi + d) ~= Exp(Jl(phi) d) Exp(phi)  (Sola eq. 144).

// [v]x, so that skew(a) * b = a x b.
Eigen::Matrix3d skew(const Eigen::Vector3d& v);

// Rotation matrix of the rotation vector phi (Rodrigues), exact near zero.
Eigen::Matrix3d expSo3(const Eigen::Vector3d& phi);

// Quaternion of the rotation vector phi.
Eigen::Quaterniond expSo3Quat(const Eigen::Vector3d& phi);

// Rotation vector of R, in [0, pi] of angle.
Eigen::Vector3d logSo3(const Eigen::Matrix3d& R);

// Right Jacobian of SO(3) and its inverse (Sola eqs. 143, 145).
Eigen::Matrix3d rightJacobianSo3(const Eigen::Vector3d& phi);
Eigen::Matrix3d rightJacobianInverseSo3(const Eigen::Vector3d& phi);

// Left Jacobian inverse; Jl^-1(phi) = Jr^-1(-phi).
Eigen::Matrix3d leftJacobianInverseSo3(const Eigen::Vector3d& phi);

// Wraps an angle to [-pi, pi).
double wrapPi(double angle_rad);

}  // namespace deepnav
