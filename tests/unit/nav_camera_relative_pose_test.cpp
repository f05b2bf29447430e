// nav/pipeline/camera_relative_pose: a camera VO result as the robot's relative pose, value and
// covariance (the covariance map checked against numeric perturbation, as every Jacobian here).
#include <gtest/gtest.h>

#include <limits>

#include "nav/pipeline/camera_relative_pose.h"

namespace deepnav {
namespace {

Eigen::Isometry3d pose(const Eigen::Vector3d& rpy, const Eigen::Vector3d& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  T.translation() = p;
  return T;
}

Eigen::Vector3d logRotation(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

VoMeasurement cameraVo(const Eigen::Isometry3d& T_cama_camb) {
  VoMeasurement vo;
  vo.valid = true;
  vo.source = VoSource::kOrb;
  vo.q_cama_camb = Eigen::Quaterniond(T_cama_camb.linear());
  vo.p_camb_in_cama_m = T_cama_camb.translation();
  vo.has_translation = true;
  return vo;
}

// Robot relative pose error [dp; dr] (dr right perturbation) of measured against nominal.
Eigen::Matrix<double, 6, 1> robotError(const RelativePoseMeasurement& nominal, const RelativePoseMeasurement& m) {
  Eigen::Matrix<double, 6, 1> e;
  e.head<3>() = m.p_robotb_in_robota_m - nominal.p_robotb_in_robota_m;
  e.tail<3>() = logRotation(nominal.q_robota_robotb.toRotationMatrix().transpose() * m.q_robota_robotb.toRotationMatrix());
  return e;
}

TEST(CameraRelativePose, EqualsTheRobotMotionSeenThroughTheMounting) {
  // GIVEN a camera mounted forward-looking with a lever arm, and two robot poses
  const Eigen::Isometry3d T_robot_cam = pose({-1.5707963, 0.1, -1.5707963}, {0.6, 0.15, -0.2});
  const Eigen::Isometry3d T_odom_ra = pose({0.05, -0.02, 0.7}, {1.0, 2.0, -10.0});
  const Eigen::Isometry3d T_odom_rb = pose({0.04, 0.01, 0.78}, {1.12, 2.05, -10.02});
  const Eigen::Isometry3d T_cama_camb = (T_odom_ra * T_robot_cam).inverse() * (T_odom_rb * T_robot_cam);
  // WHEN the camera motion is converted
  RelativePoseMeasurement m;
  ASSERT_TRUE(relativePoseFromCamera(cameraVo(T_cama_camb), T_robot_cam, 5, 9, &m));
  // THEN it is the robot motion
  const Eigen::Isometry3d T_ra_rb = T_odom_ra.inverse() * T_odom_rb;
  EXPECT_LT((m.p_robotb_in_robota_m - T_ra_rb.translation()).norm(), 1e-12);
  EXPECT_LT(logRotation(m.q_robota_robotb.toRotationMatrix().transpose() * T_ra_rb.linear()).norm(), 1e-12);
  EXPECT_EQ(m.t_us, 5);
  EXPECT_EQ(m.clone_id, 9u);
  EXPECT_EQ(m.source, kSrcVoOrb);
}

TEST(CameraRelativePose, CovarianceMatchesNumericPropagation) {
  // GIVEN a camera VO result with a full covariance (cross terms included)
  const Eigen::Isometry3d T_robot_cam = pose({-1.5707963, 0.0, -1.5707963}, {0.6, 0.15, -0.2});
  const Eigen::Isometry3d T_cama_camb = pose({0.01, -0.03, 0.08}, {0.05, -0.02, 0.2});
  VoMeasurement vo = cameraVo(T_cama_camb);
  RelativePoseMeasurement nominal;
  ASSERT_TRUE(relativePoseFromCamera(vo, T_robot_cam, 0, 1, &nominal));
  // WHEN each camera error direction is perturbed numerically
  Eigen::Matrix<double, 6, 6> J;
  const double h = 1e-7;
  for (int i = 0; i < 6; ++i) {
    Eigen::Matrix<double, 6, 1> d = Eigen::Matrix<double, 6, 1>::Zero();
    d(i) = h;
    VoMeasurement p = vo;
    p.p_camb_in_cama_m += d.head<3>();
    p.q_cama_camb = vo.q_cama_camb * Eigen::Quaterniond(Eigen::AngleAxisd(d.tail<3>().norm(), d.tail<3>().norm() > 0 ? d.tail<3>().normalized() : Eigen::Vector3d::UnitX()));
    RelativePoseMeasurement m;
    ASSERT_TRUE(relativePoseFromCamera(p, T_robot_cam, 0, 1, &m));
    J.col(i) = robotError(nominal, m) / h;
  }
  Eigen::Matrix<double, 6, 6> L = Eigen::Matrix<double, 6, 6>::Random();
  vo.cov = L * L.transpose() * 1e-4;
  RelativePoseMeasurement m;
  ASSERT_TRUE(relativePoseFromCamera(vo, T_robot_cam, 0, 1, &m));
  // THEN the analytic covariance is J C J^T
  const Eigen::Matrix<double, 6, 6> expected = J * vo.cov * J.transpose();
  EXPECT_LT((m.cov - expected).cwiseAbs().maxCoeff(), 1e-9 + 1e-5 * expected.cwiseAbs().maxCoeff());
  // AND a non-finite covariance is refused at the door
  vo.cov(2, 2) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(relativePoseFromCamera(vo, T_robot_cam, 0, 1, &m));
}

}  // namespace
}  // namespace deepnav
