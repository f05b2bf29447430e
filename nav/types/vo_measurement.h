#pragma once
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

namespace deepnav {

// Which visual odometry produced a relative pose (and which one the modality selection chose).
enum class VoSource : std::uint8_t {
  kNone = 0,
  kOrb = 1,     // ORB stereo feature tracking (good images)
  kPlanes = 2,  // dense stereo -> planes -> registration (poor images)
};

const char* toString(VoSource source);

// One visual-odometry result of a stereo pair, in the left camera's optical frame C: the pose of the
// camera at this pair's capture time (b) in the camera at the reference capture time (a). NavCore turns
// it into the EKF's RelativePoseMeasurement with the camera mounting T_robot_cam.
struct VoMeasurement {
  bool valid = false;
  VoSource source = VoSource::kNone;
  TimeUs t_reference_us = 0;  // capture time of frame a (a previous pair)
  Eigen::Quaterniond q_cama_camb = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_camb_in_cama_m = Eigen::Vector3d::Zero();
  bool has_translation = false;
  // [x y z rx ry rz]: translation error in frame a, rotation error about camera b's axes with
  // q_meas = q_true Exp(n) (the RelativePoseMeasurement convention, in camera frames).
  Eigen::Matrix<double, 6, 6> cov = Eigen::Matrix<double, 6, 6>::Identity();
  std::int32_t support = 0;  // tracked features (ORB) or matched planes (planes)
};

}  // namespace deepnav
