#include "tools/sim/sensors/camera_rig.h"

#include <gtest/gtest.h>

#include "tools/sim/rotation.h"

namespace deepnav::sim {
namespace {

TEST(SimCameraRig, OpticalFrameLooksAlongRobotXWithXRightAndYDown) {
  CameraRig rig;
  std::string error;
  ASSERT_TRUE(rig.init(CameraConfig{}, &error)) << error;
  const Eigen::Matrix3d& R = rig.R_robot_cam();
  EXPECT_LT((R.col(2) - Eigen::Vector3d::UnitX()).norm(), 1e-15);   // z forward
  EXPECT_LT((R.col(0) + Eigen::Vector3d::UnitY()).norm(), 1e-15);   // x right (robot -y)
  EXPECT_LT((R.col(1) + Eigen::Vector3d::UnitZ()).norm(), 1e-15);   // y down (robot -z)
  EXPECT_NEAR(R.determinant(), 1.0, 1e-15);
  // The right camera is one baseline to the right of the left one.
  EXPECT_LT((rig.p_right_cam_in_robot_m() - Eigen::Vector3d(0.6, -0.15, -0.2)).norm(), 1e-15);
}

TEST(SimCameraRig, TickComposesRobotPoseAndExtrinsics) {
  CameraConfig c;
  c.mount_rpy_deg = {0.0, 10.0, 0.0};  // tilted 10 deg down
  CameraRig rig;
  std::string error;
  ASSERT_TRUE(rig.init(c, &error));
  KinematicState s;
  s.p_robot_in_odom_m = {1.0, 2.0, 3.0};
  s.q_odom_robot = Eigen::AngleAxisd(kDegToRad * 90.0, Eigen::Vector3d::UnitZ());  // facing north
  const CameraTick tick = rig.tick(s, 12345, 7);
  EXPECT_EQ(tick.t_us, 12345);
  EXPECT_EQ(tick.frame_index, 7u);
  // Left camera at robot (0.6, 0.15, -0.2): north 0.6, west 0.15.
  EXPECT_LT((tick.p_left_cam_in_odom_m - Eigen::Vector3d(0.85, 2.6, 2.8)).norm(), 1e-12);
  EXPECT_LT((tick.p_right_cam_in_odom_m - Eigen::Vector3d(1.15, 2.6, 2.8)).norm(), 1e-12);
  // The optical axis points north and 10 deg down.
  const Eigen::Vector3d axis = tick.q_odom_left_cam * Eigen::Vector3d::UnitZ();
  EXPECT_LT((axis - Eigen::Vector3d(0.0, std::cos(kDegToRad * 10.0), -std::sin(kDegToRad * 10.0))).norm(), 1e-12);
}

}  // namespace
}  // namespace deepnav::sim

namespace deepnav::sim {
namespace {

TEST(SimCameraRig, TickCarriesEachCameraVelocityAndTheRateInItsOpticalFrame) {
  // GIVEN a robot facing north, moving east at 0.2 m/s and yawing left at 0.1 rad/s
  CameraRig rig;
  std::string error;
  ASSERT_TRUE(rig.init(CameraConfig{}, &error));
  KinematicState s;
  s.q_odom_robot = Eigen::AngleAxisd(kDegToRad * 90.0, Eigen::Vector3d::UnitZ());
  s.v_robot_in_odom_mps = {0.2, 0.0, 0.0};
  s.w_robot_radps = {0.0, 0.0, 0.1};
  const CameraTick tick = rig.tick(s, 0, 0);
  // THEN (optical frame: x right = robot -y, y down = robot -z, z forward = robot x) the rate is about -y
  EXPECT_LT((tick.w_cam_radps - Eigen::Vector3d(0.0, -0.1, 0.0)).norm(), 1e-12);
  // AND each camera moves at v + w x p: east is the robot's -y (the camera's +x); the yaw adds
  // w x p = 0.1 z x (0.6, +-0.15, -0.2) = (-+0.015, 0.06, 0) in the robot frame
  const Eigen::Vector3d left_in_robot(0.0 - 0.015, -0.2 + 0.06, 0.0), right_in_robot(0.0 + 0.015, -0.2 + 0.06, 0.0);
  const Eigen::Matrix3d R_cam_robot = rig.R_robot_cam().transpose();
  EXPECT_LT((tick.v_left_cam_mps - R_cam_robot * left_in_robot).norm(), 1e-12);
  EXPECT_LT((tick.v_right_cam_mps - R_cam_robot * right_in_robot).norm(), 1e-12);
  // AND the numbers agree with the motion of the camera centres over a short interval
  KinematicState later = s;
  const double dt = 1e-6;
  later.q_odom_robot = Eigen::AngleAxisd(kDegToRad * 90.0 + 0.1 * dt, Eigen::Vector3d::UnitZ());
  later.p_robot_in_odom_m = s.v_robot_in_odom_mps * dt;
  const CameraTick next = rig.tick(later, 1, 1);
  const Eigen::Vector3d v_odom = (next.p_left_cam_in_odom_m - tick.p_left_cam_in_odom_m) / dt;
  EXPECT_LT((tick.q_odom_left_cam * tick.v_left_cam_mps - v_odom).norm(), 1e-6);
}

}  // namespace
}  // namespace deepnav::sim
