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

bool checkMeasurements(const EkfConfig& c, std::string* e) {
  if (!positive(c.dvl_sigma_mps)) return fail(e, "dvl_sigma_mps", "must be > 0");
  if (!positive(c.depth_sigma_m)) return fail(e, "depth_sigma_m", "must be > 0");
  if (!positive(c.heading_sigma_rad)) return fail(e, "heading_sigma_rad", "must be > 0");
  if (!positive(c.attitude_sigma_rad)) return fail(e, "attitude_sigma_rad", "must be > 0");
  if (!std::isfinite(c.magnetic_declination_rad)) return fail(e, "magnetic_declination_rad", "must be finite");
  if (!std::isfinite(c.heading_bias_rad)) return fail(e, "heading_bias_rad", "must be finite");
  if (!positive(c.gate_dvl_sigma)) return fail(e, "gate_dvl_sigma", "must be > 0");
  if (!positive(c.gate_depth_sigma)) return fail(e, "gate_depth_sigma", "must be > 0");
  if (!positive(c.gate_heading_sigma)) return fail(e, "gate_heading_sigma", "must be > 0");
  if (!positive(c.gate_attitude_sigma)) return fail(e, "gate_attitude_sigma", "must be > 0");
  if (!positive(c.gate_pose_sigma)) return fail(e, "gate_pose_sigma", "must be > 0");
  if (!positive(c.gate_relative_pose_sigma)) return fail(e, "gate_relative_pose_sigma", "must be > 0");
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
         checkBounds(config, error) && checkMeasurements(config, error) && checkTiming(config, error);
}

}  // namespace deepnav
