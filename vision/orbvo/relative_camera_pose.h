#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "vision/orbvo/pose_refiner.h"

namespace deepnav {

// Pose of camera b in camera a with its covariance, in the order and convention of
// RelativePoseMeasurement (nav/ekf/ekf_measurements.h): [x y z roll pitch yaw] = [dp; n], the
// translation error dp in frame a and the rotation error n about the axes of b, R_meas = R_true
// Exp(n).
struct RelativeCameraPose {
  Eigen::Quaterniond q_cama_camb = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_camb_in_cama_m = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Identity();
};

// T_a_b = T_a_world T_b_world^-1 from two camera poses estimated against the same map. With the
// left perturbations xi = (dt, phi) of refineCameraPose, to first order
//   dp = dt_a - [p_ab]x phi_a - R_ab dt_b,    n = R_ba phi_a - phi_b,
// so cov = J_a cov_a J_a^T + J_b cov_b J_b^T with J_a = [[I, -[p_ab]x], [0, R_ba]], J_b =
// -diag(R_ab, I): the two poses are taken as independent given the map (their pixel noise is),
// which leaves out the map's own error, common to both and largely cancelled in the difference.
RelativeCameraPose relativeCameraPose(const CameraPoseEstimate& a, const CameraPoseEstimate& b);

}  // namespace deepnav
