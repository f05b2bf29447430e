#pragma once
#include <array>
#include <cstddef>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "nav/types/time.h"

namespace deepnav {

// The robot's recent poses (one per loop tick), to know where the robot was when an image was taken:
// vision results arrive 100-300 ms after capture, and the panel pose (T_odom_robot at the image time)
// needs the pose at the capture time, not at arrival. Fixed capacity, no allocation.
class PoseHistory {
 public:
  static constexpr std::size_t kCapacity = 256;  // 2.56 s at 100 Hz: beyond the 500 ms fusion window

  void clear() { count_ = 0; }
  void push(TimeUs t_us, const Eigen::Vector3d& p_robot_in_odom_m, const Eigen::Quaterniond& q_odom_robot);

  // Pose at t_us, linear in position and slerp in orientation between the two poses around it.
  // False when t_us is outside the stored span (older than kCapacity ticks, or in the future).
  bool poseAt(TimeUs t_us, Eigen::Isometry3d* T_odom_robot) const;

 private:
  struct Entry {
    TimeUs t_us = 0;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  };
  const Entry& at(std::size_t i) const { return entries_[(head_ + kCapacity - count_ + i) % kCapacity]; }

  std::array<Entry, kCapacity> entries_{};
  std::size_t head_ = 0;   // next write
  std::size_t count_ = 0;
};

}  // namespace deepnav
