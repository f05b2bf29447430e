#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

#include "nav/types/time.h"
#include "vision/orbvo/orb_feature.h"
#include "vision/orbvo/pose_refiner.h"

namespace deepnav {

// One stereo pair as the odometry sees it: its left features with their stereo columns and points,
// and their associations with map points (VoMap ids). Buffers are reserved once (reserve()); the
// per-pair calls do not allocate within that capacity.
struct OrbFrame {
  TimeUs t_us = 0;
  std::vector<OrbFeature> features;
  std::vector<OrbDescriptor> descriptors;
  std::vector<float> u_right_px;            // per feature, < 0 without a stereo match
  std::vector<Eigen::Vector3d> p_in_cam_m;  // per feature, its stereo point
  std::vector<int> map_point;               // per feature, -1 none
  std::vector<int> match_distance;          // per feature, Hamming distance of its map point match
  std::vector<std::uint8_t> available;      // per feature: may still take a map point
  CameraPoseEstimate pose;
  int tracked = 0;
  int stereo_points = 0;

  void reserve(int capacity) {
    features.reserve(capacity);
    descriptors.reserve(capacity);
    u_right_px.reserve(capacity);
    p_in_cam_m.reserve(capacity);
    map_point.reserve(capacity);
    match_distance.reserve(capacity);
    available.reserve(capacity);
  }

  // Every feature without a map point and free to take one.
  void clearAssociations() {
    std::fill(map_point.begin(), map_point.end(), -1);
    std::fill(match_distance.begin(), match_distance.end(), std::numeric_limits<int>::max());
    std::fill(available.begin(), available.end(), std::uint8_t{1});
  }

  int associationCount() const {
    int count = 0;
    for (const int m : map_point) count += m >= 0;
    return count;
  }
};

}  // namespace deepnav
