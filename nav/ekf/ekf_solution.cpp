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
  if (mag_.state() != MagState::kClean) bits |= kStatusMagDisturbed;
  return bits;
}

// IMU outage: the state is stuck at the last IMU sample (state_.t_us), as nothing can propagate it. The
// solution coasts on the last velocity over dt = now - state_.t_us, with its covariance grown for a white
// acceleration of density q = coast_accel_noise^2 (nearly-constant-velocity model, Bar-Shalom et al. 2001,
// sec. 6.2.2):
//   P_p += dt P_pv + dt P_vp + dt^2 P_v + q dt^3 / 3,   P_v += q dt,
// and neither its attitude nor its velocity is flagged valid. The filter itself resumes from its own
// state with the next IMU sample.
void Ekf::coast(TimeUs now_us, NavSolution* s) const {
  const double dt = usToS(now_us - state_.t_us);
  if (!(dt > 0.0)) return;
  const Eigen::Matrix3d P_pv = state_.P.block<3, 3>(es::kP, es::kV);
  const Eigen::Matrix3d P_v = state_.P.block<3, 3>(es::kV, es::kV);
  const double a2 = config_.coast_accel_noise_mps2_rthz * config_.coast_accel_noise_mps2_rthz;
  s->p_robot_in_odom_m += dt * s->v_robot_in_odom_mps;
  s->cov_pose.block<3, 3>(0, 0) += dt * (P_pv + P_pv.transpose()) + dt * dt * P_v +
                                   Eigen::Matrix3d::Identity() * (a2 * dt * dt * dt / 3.0);
  const Eigen::Matrix3d P_vtheta = state_.P.block<3, 3>(es::kV, es::kTheta);
  s->cov_pose.block<3, 3>(0, 3) += dt * P_vtheta;
  s->cov_pose.block<3, 3>(3, 0) += dt * P_vtheta.transpose();
  s->cov_v_mps2 += Eigen::Matrix3d::Identity() * (a2 * dt);
  s->status &= ~(kStatusAttitudeValid | kStatusVelocityValid);
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
  if (aligned_ && health_.isStale(kSrcImu, now)) coast(now, &s);
  s.faults = initialised_ ? health_.faultBits(now) : 0;
  s.rejected_total = health_.rejectedTotal();
  s.dropped_late_total = health_.droppedLateTotal();
  return s;
}

}  // namespace deepnav
