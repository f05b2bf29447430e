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
