// Ekf::solution(): the filter state as the loop's NavSolution (pose, velocity, covariances, health).
#include <algorithm>

#include "nav/ekf/ekf.h"

namespace deepnav {

std::uint32_t Ekf::statusBits(TimeUs now_us) const {
  if (!aligned_) return 0;
  std::uint32_t bits = kStatusAttitudeValid;
  if (health_.acceptedWithin(kSrcDvl, now_us, config_.timeout_dvl_us)) bits |= kStatusVelocityValid;
  if (health_.acceptedWithin(kSrcDepth, now_us, config_.timeout_depth_us)) bits |= kStatusDepthValid;
  const TimeUs window = config_.position_aided_timeout_us;
  if (health_.acceptedWithin(kSrcMarkers, now_us, window) || health_.acceptedWithin(kSrcVoOrb, now_us, window) ||
      health_.acceptedWithin(kSrcVoPlanes, now_us, window)) {
    bits |= kStatusPositionValid;
  }
  return bits;
}

NavSolution Ekf::solution() const { return solution(0); }

NavSolution Ekf::solution(TimeUs now_us) const {
  NavSolution s;
  const TimeUs now = std::max({now_us, latest_input_t_us_, state_.t_us});
  s.t_us = state_.t_us;
  s.p_robot_in_odom_m = state_.x.p_robot_in_odom_m;
  s.q_odom_robot = state_.x.q_odom_robot;
  s.v_robot_in_odom_mps = state_.x.v_robot_in_odom_mps;
  s.w_robot_radps = state_.w_robot_meas_radps - state_.x.b_gyro_radps;
  // ROS order [x y z roll pitch yaw]; dtheta is already about the odom axes (error_state.h).
  s.cov_pose.block<3, 3>(0, 0) = state_.P.block<3, 3>(es::kP, es::kP);
  s.cov_pose.block<3, 3>(0, 3) = state_.P.block<3, 3>(es::kP, es::kTheta);
  s.cov_pose.block<3, 3>(3, 0) = state_.P.block<3, 3>(es::kTheta, es::kP);
  s.cov_pose.block<3, 3>(3, 3) = state_.P.block<3, 3>(es::kTheta, es::kTheta);
  s.cov_v_mps2 = state_.P.block<3, 3>(es::kV, es::kV);
  s.stage = aligned_ ? NavStage::kWorkspace : NavStage::kInit;  // the stage machine refines this
  s.status = statusBits(now);
  s.faults = initialised_ ? health_.faultBits(now) : 0;
  s.rejected_total = health_.rejectedTotal();
  s.dropped_late_total = health_.droppedLateTotal();
  return s;
}

}  // namespace deepnav
