#include "board/config/euroc_mounting.h"

#include <algorithm>
#include <cmath>

#include "drivers/euroc/euroc_frames.h"

namespace deepnav {
namespace {

CameraCalibration cameraCalibration(const EurocCamera& c) {
  CameraCalibration k;
  k.K = cv::Matx33d(c.intrinsics[0], 0.0, c.intrinsics[2], 0.0, c.intrinsics[1], c.intrinsics[3], 0.0, 0.0, 1.0);
  k.dist = cv::Mat(1, 4, CV_64F);
  for (int i = 0; i < 4; ++i) k.dist.at<double>(0, i) = c.distortion[static_cast<std::size_t>(i)];
  return k;
}

// camera.rotation_deg of a camera whose optical frame is R_robot_optical: the board composes
// q_robot_body * body_from_optical (vehicle_setup.cpp, camera body FLU with x = optical z) and reads the
// angles as Rz(yaw) Ry(pitch) Rx(roll) (param_table.cpp).
Eigen::Vector3d rotationDeg(const Eigen::Matrix3d& R_robot_optical) {
  Eigen::Matrix3d body_from_optical;
  body_from_optical << 0, 0, 1,  //
      -1, 0, 0,                  //
      0, -1, 0;
  const Eigen::Matrix3d R = R_robot_optical * body_from_optical.transpose();
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  const double roll = std::atan2(R(2, 1), R(2, 2));
  const double yaw = std::atan2(R(1, 0), R(0, 0));
  return Eigen::Vector3d(roll, pitch, yaw) * (180.0 / M_PI);
}

}  // namespace

EurocMounting eurocMounting(const EurocCamera& cam0, const EurocCamera& cam1, const EurocImuInfo& imu) {
  EurocMounting m;
  StereoCalibration& s = m.calibration;
  s.image_size = cv::Size(cam0.width_px, cam0.height_px);
  s.left = cameraCalibration(cam0);
  s.right = cameraCalibration(cam1);
  const Eigen::Matrix3d R0 = cam0.T_body_sensor.linear(), R1 = cam1.T_body_sensor.linear();
  const Eigen::Matrix3d R = R1.transpose() * R0;
  const Eigen::Vector3d T = R1.transpose() * (cam0.T_body_sensor.translation() - cam1.T_body_sensor.translation());
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) s.R(i, j) = R(i, j);
    s.T(i) = T(i);
  }
  m.baseline_m = T.norm();
  const Eigen::Matrix3d R_robot_body = eurocRobotFromBody();
  m.p_cam_in_robot_m = R_robot_body * cam0.T_body_sensor.translation();
  m.camera_rotation_deg = rotationDeg(R_robot_body * R0);
  m.p_imu_in_robot_m = R_robot_body * imu.T_body_sensor.translation();
  return m;
}

}  // namespace deepnav
