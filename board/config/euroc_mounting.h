#pragma once
#include <Eigen/Core>

#include "drivers/euroc/euroc_sensor.h"
#include "vision/calib/stereo_calibration.h"

namespace deepnav {

// The EuRoC rig in deepnav's terms: the stereo calibration of the raw images and the board's mounting
// keys, from the cameras' and the IMU's sensor.yaml (T_BS, intrinsics, distortion). Robot frame R: FLU at
// the body origin (drivers/euroc/euroc_frames.h).
struct EurocMounting {
  StereoCalibration calibration;      // camera.calibration_file
  Eigen::Vector3d p_cam_in_robot_m;   // camera.p_cam_in_robot_m: cam0's optical centre
  Eigen::Vector3d camera_rotation_deg;  // camera.rotation_deg: [roll, pitch, yaw] of the camera body
  Eigen::Vector3d p_imu_in_robot_m;   // ekf.p_imu_in_robot_m (the IMU samples are rotated to R at import)
  double baseline_m = 0.0;            // |T|
};

// From T_BS of both cameras: p_c1 = R p_c0 + T with R = R_BS1^T R_BS0, T = R_BS1^T (t_BS0 - t_BS1)
// (vision/calib/stereo_calibration.h); K = [fu 0 cu; 0 fv cv; 0 0 1], dist = k1 k2 p1 p2.
EurocMounting eurocMounting(const EurocCamera& cam0, const EurocCamera& cam1, const EurocImuInfo& imu);

}  // namespace deepnav
