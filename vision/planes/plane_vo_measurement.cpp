#include "vision/planes/plane_vo_measurement.h"

namespace deepnav {
namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

}  // namespace

bool toRelativePoseMeasurement(const PlaneRegistrationResult& registration,
                               const Eigen::Isometry3d& T_robot_cam, TimeUs t_b_us,
                               std::uint32_t clone_id, RelativePoseMeasurement* measurement) {
  if (measurement == nullptr || !registration.valid) return false;
  const Eigen::Matrix3d R_rc = T_robot_cam.linear();
  const Eigen::Vector3d p_cam_in_robot = T_robot_cam.translation();
  const Eigen::Quaterniond q_rc(R_rc);
  const Eigen::Quaterniond q_ab = (q_rc * registration.q_cama_camb * q_rc.inverse()).normalized();
  const Eigen::Matrix3d R_ab = q_ab.toRotationMatrix();

  RelativePoseMeasurement& m = *measurement;
  m = RelativePoseMeasurement{};
  m.t_us = t_b_us;
  m.clone_id = clone_id;
  m.source = kSrcVoPlanes;
  m.q_robota_robotb = q_ab;
  m.has_translation = registration.has_translation;
  m.p_robotb_in_robota_m =
      R_rc * registration.p_camb_in_cama_m + p_cam_in_robot - R_ab * p_cam_in_robot;

  const Eigen::Matrix3d C_rot =
      R_rc * registration.cov.bottomRightCorner<3, 3>() * R_rc.transpose();
  m.cov.setZero();
  m.cov.bottomRightCorner<3, 3>() = C_rot;
  if (registration.has_translation) {
    const Eigen::Matrix3d J = R_ab * skew(p_cam_in_robot);
    m.cov.topLeftCorner<3, 3>() = R_rc * registration.cov.topLeftCorner<3, 3>() * R_rc.transpose() +
                                  J * C_rot * J.transpose();
    m.cov.topRightCorner<3, 3>() = J * C_rot;
    m.cov.bottomLeftCorner<3, 3>() = (J * C_rot).transpose();
  } else {
    m.cov.topLeftCorner<3, 3>() = registration.cov.topLeftCorner<3, 3>();
  }
  return true;
}

}  // namespace deepnav
