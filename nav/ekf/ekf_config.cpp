#include "nav/ekf/ekf_config.h"

#include <cmath>

#include "nav/ekf/error_state.h"

namespace deepnav {
namespace {

bool fail(std::string* error, const char* key, const char* why) {
  if (error != nullptr) *error = std::string("EkfConfig.") + key + ": " + why;
  return false;
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }
bool nonNegative(double v) { return std::isfinite(v) && v >= 0.0; }
bool unitQuaternion(const Eigen::Quaterniond& q) {
  return q.coeffs().allFinite() && std::abs(q.norm() - 1.0) < 1e-6;
}
bool bounds(double lo, double hi) { return positive(lo) && positive(hi) && lo < hi; }

bool checkGeometry(const EkfConfig& c, std::string* e) {
  if (!positive(c.gravity_mps2) || c.gravity_mps2 > 20.0) return fail(e, "gravity_mps2", "must be in (0, 20]");
  if (!unitQuaternion(c.q_robot_imu)) return fail(e, "q_robot_imu", "must be a unit quaternion");
  if (!unitQuaternion(c.q_robot_dvl)) return fail(e, "q_robot_dvl", "must be a unit quaternion");
  if (!c.p_imu_in_robot_m.allFinite()) return fail(e, "p_imu_in_robot_m", "must be finite");
  if (!c.p_dvl_in_robot_m.allFinite()) return fail(e, "p_dvl_in_robot_m", "must be finite");
  if (!c.p_depth_in_robot_m.allFinite()) return fail(e, "p_depth_in_robot_m", "must be finite");
  return true;
}

bool checkImu(const EkfConfig& c, std::string* e) {
  if (!positive(c.gyro_arw_radps_rthz)) return fail(e, "gyro_arw_radps_rthz", "must be > 0");
  if (!positive(c.accel_vrw_mps2_rthz)) return fail(e, "accel_vrw_mps2_rthz", "must be > 0");
  if (!nonNegative(c.gyro_bias_rw_radps2_rthz)) return fail(e, "gyro_bias_rw_radps2_rthz", "must be >= 0");
  if (!nonNegative(c.accel_bias_rw_mps3_rthz)) return fail(e, "accel_bias_rw_mps3_rthz", "must be >= 0");
  if (!positive(c.imu_max_rate_radps)) return fail(e, "imu_max_rate_radps", "must be > 0");
  if (!positive(c.imu_max_accel_mps2)) return fail(e, "imu_max_accel_mps2", "must be > 0");
  if (c.imu_max_gap_us <= 0) return fail(e, "imu_max_gap_us", "must be > 0");
  return true;
}

bool checkInitial(const EkfConfig& c, std::string* e) {
  if (!positive(c.init_pos_sigma_m)) return fail(e, "init_pos_sigma_m", "must be > 0");
  if (!positive(c.init_vel_sigma_mps)) return fail(e, "init_vel_sigma_mps", "must be > 0");
  if (!positive(c.init_roll_pitch_sigma_rad)) return fail(e, "init_roll_pitch_sigma_rad", "must be > 0");
  if (!positive(c.init_yaw_sigma_rad)) return fail(e, "init_yaw_sigma_rad", "must be > 0");
  if (!positive(c.init_gyro_bias_sigma_radps)) return fail(e, "init_gyro_bias_sigma_radps", "must be > 0");
  if (!positive(c.init_accel_bias_sigma_mps2)) return fail(e, "init_accel_bias_sigma_mps2", "must be > 0");
  return true;
}

bool checkBounds(const EkfConfig& c, std::string* e) {
  if (!bounds(c.pos_var_min_m2, c.pos_var_max_m2)) return fail(e, "pos_var_min_m2", "need 0 < min < max");
  if (!bounds(c.vel_var_min_m2ps2, c.vel_var_max_m2ps2)) return fail(e, "vel_var_min_m2ps2", "need 0 < min < max");
  if (!bounds(c.angle_var_min_rad2, c.angle_var_max_rad2)) return fail(e, "angle_var_min_rad2", "need 0 < min < max");
  if (!bounds(c.gyro_bias_var_min_rad2ps2, c.gyro_bias_var_max_rad2ps2)) {
    return fail(e, "gyro_bias_var_min_rad2ps2", "need 0 < min < max");
  }
  if (!bounds(c.accel_bias_var_min_m2ps4, c.accel_bias_var_max_m2ps4)) {
    return fail(e, "accel_bias_var_min_m2ps4", "need 0 < min < max");
  }
  return true;
}

bool checkMagDisturbance(const EkfConfig& c, std::string* e) {
  if (!positive(c.mag_disturbance_tau_s) || c.mag_disturbance_tau_s > 600.0) {
    return fail(e, "mag_disturbance_tau_s", "must be in (0, 600]");
  }
  if (!positive(c.mag_disturbance_exit_sigma)) return fail(e, "mag_disturbance_exit_sigma", "must be > 0");
  if (!(c.mag_disturbance_suspect_sigma > c.mag_disturbance_exit_sigma) ||
      !std::isfinite(c.mag_disturbance_suspect_sigma)) {
    return fail(e, "mag_disturbance_suspect_sigma", "must be finite and > mag_disturbance_exit_sigma");
  }
  if (!(c.mag_disturbance_enter_sigma >= c.mag_disturbance_suspect_sigma) ||
      !std::isfinite(c.mag_disturbance_enter_sigma)) {
    return fail(e, "mag_disturbance_enter_sigma", "must be finite and >= mag_disturbance_suspect_sigma");
  }
  if (c.mag_disturbance_exit_hold_us < 0) return fail(e, "mag_disturbance_exit_hold_us", "must be >= 0");
  if (!(c.mag_disturbance_r_scale >= 1.0) || !std::isfinite(c.mag_disturbance_r_scale)) {
    return fail(e, "mag_disturbance_r_scale", "must be finite and >= 1");
  }
  if (!positive(c.mag_disturbance_yaw_held_ratio)) return fail(e, "mag_disturbance_yaw_held_ratio", "must be > 0");
  if (c.mag_disturbance_aided_window_us <= 0) return fail(e, "mag_disturbance_aided_window_us", "must be > 0");
  return true;
}

bool checkMeasurements(const EkfConfig& c, std::string* e) {
  if (!positive(c.dvl_sigma_mps)) return fail(e, "dvl_sigma_mps", "must be > 0");
  if (!positive(c.depth_sigma_m)) return fail(e, "depth_sigma_m", "must be > 0");
  if (!positive(c.heading_sigma_rad)) return fail(e, "heading_sigma_rad", "must be > 0");
  if (!positive(c.attitude_sigma_rad)) return fail(e, "attitude_sigma_rad", "must be > 0");
  if (!std::isfinite(c.magnetic_declination_rad)) return fail(e, "magnetic_declination_rad", "must be finite");
  if (!std::isfinite(c.heading_bias_rad)) return fail(e, "heading_bias_rad", "must be finite");
  if (!checkMagDisturbance(c, e)) return false;
  if (!positive(c.gate_dvl_sigma)) return fail(e, "gate_dvl_sigma", "must be > 0");
  if (!positive(c.gate_depth_sigma)) return fail(e, "gate_depth_sigma", "must be > 0");
  if (!positive(c.gate_heading_sigma)) return fail(e, "gate_heading_sigma", "must be > 0");
  if (!positive(c.gate_attitude_sigma)) return fail(e, "gate_attitude_sigma", "must be > 0");
  if (!positive(c.gate_pose_sigma)) return fail(e, "gate_pose_sigma", "must be > 0");
  if (!positive(c.gate_relative_pose_sigma)) return fail(e, "gate_relative_pose_sigma", "must be > 0");
  return true;
}

bool checkSystematic(const EkfConfig& c, std::string* e) {
  if (!nonNegative(c.dvl_scale_prior_sigma) || c.dvl_scale_prior_sigma > 0.2) {
    return fail(e, "dvl_scale_prior_sigma", "must be in [0, 0.2]");
  }
  if (!nonNegative(c.dvl_bias_prior_sigma_mps) || c.dvl_bias_prior_sigma_mps > 0.5) {
    return fail(e, "dvl_bias_prior_sigma_mps", "must be in [0, 0.5] m/s");
  }
  if (!nonNegative(c.dvl_misalignment_prior_sigma_rad) || c.dvl_misalignment_prior_sigma_rad > 0.2) {
    return fail(e, "dvl_misalignment_prior_sigma_rad", "must be in [0, 0.2] rad");
  }
  if (!nonNegative(c.heading_bias_prior_sigma_rad) || c.heading_bias_prior_sigma_rad > 0.5) {
    return fail(e, "heading_bias_prior_sigma_rad", "must be in [0, 0.5] rad");
  }
  if (!nonNegative(c.heading_deviation_prior_sigma_rad) || c.heading_deviation_prior_sigma_rad > 0.5) {
    return fail(e, "heading_deviation_prior_sigma_rad", "must be in [0, 0.5] rad");
  }
  if (!nonNegative(c.heading_sigma_floor_rad) || c.heading_sigma_floor_rad > 1.0) {
    return fail(e, "heading_sigma_floor_rad", "must be in [0, 1] rad");
  }
  const auto tau_ok = [](double tau) { return tau == 0.0 || (std::isfinite(tau) && tau >= 1.0 && tau <= 1e6); };
  if (!tau_ok(c.gyro_bias_gm_tau_s)) return fail(e, "gyro_bias_gm_tau_s", "must be 0 (off) or in [1, 1e6] s");
  if (!tau_ok(c.accel_bias_gm_tau_s)) return fail(e, "accel_bias_gm_tau_s", "must be 0 (off) or in [1, 1e6] s");
  if (!nonNegative(c.gyro_bias_gm_sigma_radps) || c.gyro_bias_gm_sigma_radps > 0.1) {
    return fail(e, "gyro_bias_gm_sigma_radps", "must be in [0, 0.1] rad/s");
  }
  if (!nonNegative(c.accel_bias_gm_sigma_mps2) || c.accel_bias_gm_sigma_mps2 > 1.0) {
    return fail(e, "accel_bias_gm_sigma_mps2", "must be in [0, 1] m/s^2");
  }
  return true;
}

bool checkTiming(const EkfConfig& c, std::string* e) {
  if (c.timeout_imu_us < 0) return fail(e, "timeout_imu_us", "must be >= 0");
  if (c.timeout_dvl_us < 0) return fail(e, "timeout_dvl_us", "must be >= 0");
  if (c.timeout_depth_us < 0) return fail(e, "timeout_depth_us", "must be >= 0");
  if (c.timeout_heading_us < 0) return fail(e, "timeout_heading_us", "must be >= 0");
  if (c.timeout_attitude_us < 0) return fail(e, "timeout_attitude_us", "must be >= 0");
  if (c.timeout_markers_us < 0) return fail(e, "timeout_markers_us", "must be >= 0");
  if (c.timeout_vo_us < 0) return fail(e, "timeout_vo_us", "must be >= 0");
  if (c.position_aided_timeout_us < 0) return fail(e, "position_aided_timeout_us", "must be >= 0");
  if (c.max_delay_us < 0) return fail(e, "max_delay_us", "must be >= 0");
  if (c.history_imu_capacity < 2 || c.history_imu_capacity > 100'000) {
    return fail(e, "history_imu_capacity", "must be in [2, 100000]");
  }
  if (c.history_meas_capacity < 1 || c.history_meas_capacity > 100'000) {
    return fail(e, "history_meas_capacity", "must be in [1, 100000]");
  }
  if (c.max_clones < 1 || c.max_clones > es::kMaxClones) return fail(e, "max_clones", "must be in [1, es::kMaxClones]");
  if (c.align_imu_samples < 1) return fail(e, "align_imu_samples", "must be >= 1");
  if (c.imu_stuck_after_samples < 0 || c.imu_stuck_after_samples == 1) {
    return fail(e, "imu_stuck_after_samples", "must be 0 (off) or >= 2");
  }
  if (c.stuck_after_samples < 0 || c.stuck_after_samples == 1) {
    return fail(e, "stuck_after_samples", "must be 0 (off) or >= 2");
  }
  if (c.gate_reset_after_us < 0) return fail(e, "gate_reset_after_us", "must be >= 0");
  if (!(c.coast_accel_noise_mps2_rthz >= 0.0) || !std::isfinite(c.coast_accel_noise_mps2_rthz)) {
    return fail(e, "coast_accel_noise_mps2_rthz", "must be finite and >= 0");
  }
  return true;
}

}  // namespace

bool validateEkfConfig(const EkfConfig& config, std::string* error) {
  return checkGeometry(config, error) && checkImu(config, error) && checkInitial(config, error) &&
         checkBounds(config, error) && checkMeasurements(config, error) && checkSystematic(config, error) &&
         checkTiming(config, error);
}

}  // namespace deepnav
