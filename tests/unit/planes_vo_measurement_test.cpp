#include <gtest/gtest.h>

#include <cmath>

#include "nav/ekf/ekf_measurements.h"
#include "nav/pipeline/camera_relative_pose.h"
#include "vision/planes/plane_registration.h"

namespace deepnav {
namespace {

// The plane registration (camera frames) as the EKF's relative pose measurement (robot frames), the
// way the nav side fuses a plane VoMeasurement (relativePoseFromCamera):
//   T_robota_robotb = T_robot_cam T_cama_camb T_robot_cam^-1,
//   p_robotb_in_robota = R_rc t_c + p_cam_in_robot - R_ab p_cam_in_robot,
// rotation error delta_r = R_rc delta_c (both right perturbations), translation covariance
// R_rc C_t R_rc^T + J C_rot J^T with J = R_ab [p_cam_in_robot]x (the lever arm turns with the
// rotation error), cross covariance J C_rot. Order [x y z roll pitch yaw] as in
// RelativePoseMeasurement. False when the registration is not valid (rotation not fully observed).
bool toRelativePoseMeasurement(const PlaneRegistrationResult& registration,
                               const Eigen::Isometry3d& T_robot_cam, TimeUs t_b_us,
                               std::uint32_t clone_id, RelativePoseMeasurement* measurement) {
  if (!registration.valid) return false;
  VoMeasurement vo;
  vo.valid = true;
  vo.source = VoSource::kPlanes;
  vo.q_cama_camb = registration.q_cama_camb;
  vo.p_camb_in_cama_m = registration.p_camb_in_cama_m;
  vo.has_translation = registration.has_translation;
  vo.cov = registration.cov;
  vo.support = registration.matched_planes;
  return relativePoseFromCamera(vo, T_robot_cam, t_b_us, clone_id, measurement);
}

// Rotation vector of a rotation matrix (log map).
Eigen::Vector3d logMap(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

Eigen::Matrix3d expMap(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, v / angle).toRotationMatrix();
}

// The camera-frame motion x = (t_c, delta_c) mapped to robot-frame (p_r, delta_r) around the
// registration's estimate.
Eigen::Matrix<double, 6, 1> toRobot(const Eigen::Quaterniond& q_c, const Eigen::Vector3d& t_c,
                                    const Eigen::Matrix<double, 6, 1>& x,
                                    const Eigen::Isometry3d& T_rc) {
  const Eigen::Matrix3d R_c = q_c.toRotationMatrix() * expMap(x.tail<3>());
  const Eigen::Matrix3d R_c_hat = q_c.toRotationMatrix();
  const Eigen::Matrix3d R_rc = T_rc.linear();
  const Eigen::Vector3d p = T_rc.translation();
  const Eigen::Matrix3d R_r = R_rc * R_c * R_rc.transpose();
  const Eigen::Matrix3d R_r_hat = R_rc * R_c_hat * R_rc.transpose();
  Eigen::Matrix<double, 6, 1> y;
  y.head<3>() = R_rc * (t_c + x.head<3>()) + p - R_r * p;
  y.tail<3>() = logMap(R_r_hat.transpose() * R_r);
  return y;
}

TEST(PlaneVoMeasurement, RobotFrameMotionAndCovarianceMatchNumericPropagation) {
  // GIVEN a camera looking forward-down on the robot, 0.8 m ahead and 0.3 m below its origin,
  // and a registration with translation and a full covariance
  Eigen::Isometry3d T_robot_cam = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d R_rc;  // optical z forward (robot x), x right (-robot y), y down (-robot z)
  R_rc << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  T_robot_cam.linear() = R_rc * Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()).toRotationMatrix();
  T_robot_cam.translation() = Eigen::Vector3d(0.8, 0.1, -0.3);
  PlaneRegistrationResult reg;
  reg.valid = true;
  reg.has_translation = true;
  reg.q_cama_camb =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.05, Eigen::Vector3d(1, 2, 3).normalized()));
  reg.p_camb_in_cama_m = Eigen::Vector3d(0.05, -0.02, 0.1);
  Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Random() * 0.01;
  reg.cov = A * A.transpose() + 1e-6 * Eigen::Matrix<double, 6, 6>::Identity();
  reg.cov.topRightCorner<3, 3>().setZero();  // decoupled, as the registration reports
  reg.cov.bottomLeftCorner<3, 3>().setZero();

  // WHEN converted
  RelativePoseMeasurement m;
  ASSERT_TRUE(toRelativePoseMeasurement(reg, T_robot_cam, 123, 7, &m));

  // THEN the motion is the conjugated camera motion
  const Eigen::Isometry3d T_ca_cb = Eigen::Translation3d(reg.p_camb_in_cama_m) * reg.q_cama_camb;
  const Eigen::Isometry3d T_ra_rb = T_robot_cam * T_ca_cb * T_robot_cam.inverse();
  EXPECT_LT(m.q_robota_robotb.angularDistance(Eigen::Quaterniond(T_ra_rb.linear())), 1e-12);
  EXPECT_LT((m.p_robotb_in_robota_m - T_ra_rb.translation()).norm(), 1e-12);
  EXPECT_EQ(m.t_us, 123);
  EXPECT_EQ(m.clone_id, 7u);
  EXPECT_EQ(m.source, kSrcVoPlanes);
  EXPECT_TRUE(m.has_translation);
  // THEN the covariance is the numeric propagation J C J^T
  Eigen::Matrix<double, 6, 6> J;
  const double h = 1e-6;
  for (int i = 0; i < 6; ++i) {
    Eigen::Matrix<double, 6, 1> dx = Eigen::Matrix<double, 6, 1>::Zero();
    dx(i) = h;
    J.col(i) = (toRobot(reg.q_cama_camb, reg.p_camb_in_cama_m, dx, T_robot_cam) -
                toRobot(reg.q_cama_camb, reg.p_camb_in_cama_m, -dx, T_robot_cam)) /
               (2.0 * h);
  }
  const Eigen::Matrix<double, 6, 6> expected = J * reg.cov * J.transpose();
  EXPECT_LT((m.cov - expected).norm(), 1e-8 * expected.norm()) << m.cov << "\n\n" << expected;
}

TEST(PlaneVoMeasurement, InvalidRegistrationIsNotAMeasurement) {
  PlaneRegistrationResult reg;  // valid = false
  RelativePoseMeasurement m;
  EXPECT_FALSE(toRelativePoseMeasurement(reg, Eigen::Isometry3d::Identity(), 0, 0, &m));
}

}  // namespace
}  // namespace deepnav
