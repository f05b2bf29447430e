#pragma once
#include <array>
#include <string>

#include <Eigen/Geometry>

namespace deepnav {

// A camera as its EuRoC sensor.yaml describes it. T_BS maps points of the sensor (camera optical frame:
// z forward, x right, y down) into the body frame B of the dataset: p_B = T_BS * p_S.
struct EurocCamera {
  Eigen::Isometry3d T_body_sensor = Eigen::Isometry3d::Identity();
  double rate_hz = 0.0;
  int width_px = 0;
  int height_px = 0;
  std::array<double, 4> intrinsics{};  // fu, fv, cu, cv (px)
  std::array<double, 4> distortion{};  // radial-tangential: k1, k2, p1, p2 (OpenCV order)
};

// The IMU's sensor.yaml: T_BS, rate and the noise model (continuous-time densities).
struct EurocImuInfo {
  Eigen::Isometry3d T_body_sensor = Eigen::Isometry3d::Identity();
  double rate_hz = 0.0;
  double gyro_noise_density_radps_rthz = 0.0;
  double gyro_random_walk_radps2_rthz = 0.0;
  double accel_noise_density_mps2_rthz = 0.0;
  double accel_random_walk_mps3_rthz = 0.0;
};

// Readers of mav0/camN/sensor.yaml and mav0/imu0/sensor.yaml. Only the pinhole model with
// radial-tangential distortion is read (the EuRoC cameras); T_BS must be a rigid transform (4x4, last row
// 0 0 0 1, orthonormal rotation). Errors name the file, the line and the key.
bool readEurocCamera(const std::string& path, EurocCamera* camera, std::string* error);
bool readEurocImuInfo(const std::string& path, EurocImuInfo* imu, std::string* error);

}  // namespace deepnav
