#include "nav/pipeline/camera_relative_pose.h"

namespace deepnav {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

bool relativePoseFromCamera(const VoMeasurement& vo, const Eigen::Isometry3d& T_robot_cam, TimeUs t_b_us,
                            std::uint32_t clone_id, RelativePoseMeasurement* measurement) {
  if (measurement == nullptr || !vo.valid || !vo.cov.allFinite() || !vo.p_camb_in_cama_m.allFinite() ||
      !vo.q_cama_camb.coeffs().allFinite()) {
    return false;
  }
  const Eigen::Matrix3d R_rc = T_robot_cam.linear();
  const Eigen::Vector3d p_cam_in_robot = T_robot_cam.translation();
  const Eigen::Quaterniond q_rc(R_rc);
  const Eigen::Quaterniond q_ab = (q_rc * vo.q_cama_camb.normalized() * q_rc.inverse()).normalized();
  const Eigen::Matrix3d R_ab = q_ab.toRotationMatrix();

  RelativePoseMeasurement& m = *measurement;
  m = RelativePoseMeasurement{};
  m.t_us = t_b_us;
  m.clone_id = clone_id;
  m.source = vo.source == VoSource::kPlanes ? kSrcVoPlanes : kSrcVoOrb;
  m.q_robota_robotb = q_ab;
  m.has_translation = vo.has_translation;
  m.p_robotb_in_robota_m = R_rc * vo.p_camb_in_cama_m + p_cam_in_robot - R_ab * p_cam_in_robot;

  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
  A.topLeftCorner<3, 3>() = R_rc;
  A.topRightCorner<3, 3>() = R_ab * skew(p_cam_in_robot) * R_rc;
  A.bottomRightCorner<3, 3>() = R_rc;
  m.cov = A * vo.cov * A.transpose();
  m.cov = 0.5 * (m.cov + m.cov.transpose());
  return true;
}

}  // namespace deepnav
