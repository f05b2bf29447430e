#include "vision/orbvo/relative_camera_pose.h"

#include "base/so3.h"

namespace deepnav {

RelativeCameraPose relativeCameraPose(const CameraPoseEstimate& a, const CameraPoseEstimate& b) {
  const Eigen::Matrix3d R_ab = a.R_cam_world * b.R_cam_world.transpose();
  const Eigen::Vector3d p_ab = a.p_world_in_cam_m - R_ab * b.p_world_in_cam_m;
  Eigen::Matrix<double, 6, 6> J_a = Eigen::Matrix<double, 6, 6>::Zero();
  J_a.topLeftCorner<3, 3>().setIdentity();
  J_a.topRightCorner<3, 3>() = -skew(p_ab);
  J_a.bottomRightCorner<3, 3>() = R_ab.transpose();
  Eigen::Matrix<double, 6, 6> J_b = Eigen::Matrix<double, 6, 6>::Zero();
  J_b.topLeftCorner<3, 3>() = -R_ab;
  J_b.bottomRightCorner<3, 3>() = -Eigen::Matrix3d::Identity();
  RelativeCameraPose out;
  out.q_cama_camb = Eigen::Quaterniond(R_ab).normalized();
  out.p_camb_in_cama_m = p_ab;
  out.cov = J_a * a.cov_xi * J_a.transpose() + J_b * b.cov_xi * J_b.transpose();
  out.cov = 0.5 * (out.cov + out.cov.transpose()).eval();
  return out;
}

}  // namespace deepnav
