#pragma once
#include <cstdint>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

namespace deepnav {

// The instant a stereo pair is exposed, with the true pose of each camera's optical frame (z forward,
// x right, y down) in the odometry frame. The renderer draws the pair from these poses.
struct CameraTick {
  TimeUs t_us = 0;           // the pair's stamp (the camera clock's, shifted by `timing.camera`)
  TimeUs exposure_t_us = 0;  // the true instant of the exposure, at which the poses below are taken
  std::uint32_t frame_index = 0;
  Eigen::Vector3d p_left_cam_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_left_cam = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_right_cam_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_right_cam = Eigen::Quaterniond::Identity();
  // The rig's motion at the instant, each in the camera's own optical frame: the velocity of each optical
  // centre and the angular rate (motion blur, tools/sim/render/motion_blur.h). Zero for a still view.
  Eigen::Vector3d v_left_cam_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_right_cam_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d w_cam_radps = Eigen::Vector3d::Zero();
  bool corrupted = false;  // `garbage` fault: the recorded images are noise (tools/sim/faults/frame_corruption.h)
};

}  // namespace deepnav
