#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "nav/types/time.h"

namespace deepnav {

// Ground truth of one simulated stereo pair (topics /truth/frame, /truth/depth, /truth/disparity).
// Poses are in the recording's odometry frame (the one of /truth/odometry); camera frames are optical
// (z forward, x right, y down). Maps are of the left image.
struct FrameTruth {
  TimeUs t_us = 0;              // capture time: the stamp of the pair's StereoInfo and images
  std::uint64_t sequence = 0;   // the pair's sequence
  Eigen::Vector3d p_robot_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_robot = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_left_cam_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_left_cam = Eigen::Quaterniond::Identity();
  Eigen::Vector3d p_right_cam_in_odom_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_odom_right_cam = Eigen::Quaterniond::Identity();
  std::vector<int> visible_marker_ids;  // ascending
  cv::Mat depth_m;       // CV_32FC1, along the optical axis; 0 = no surface within range (open water)
  cv::Mat disparity_px;  // CV_32FC1, fx * baseline / depth; 0 where depth is 0. Recorded in 1/128 px
                         // steps (truth_codec.h), so it equals fx * B / depth within 1/256 px.
};

}  // namespace deepnav
