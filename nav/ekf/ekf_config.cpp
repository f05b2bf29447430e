#include "nav/ekf/ekf_config.h"

#include <array>
#include <cmath>

#include "nav/ekf/error_state.h"

namespace deepnav {
namespace {

using D = ParamDecl<EkfConfig>;

// The board keys of the filter, in the order `deepnav config --list` prints them. Ranges are the
// physically sound ones for an underwater vehicle (gravity 9.7-9.9 m/s^2 anywhere on Earth's surface).
const std::array kEkfParams = {
    D{"gravity_mps2", ParamType::kDouble, "m/s^2", 9.7, 9.9, "",
      "local gravity magnitude",
      DEEPNAV_PARAM_FIELD(EkfConfig, gravity_mps2)},
    D{"imu_rotation_deg", ParamType::kRotation, "deg", -180, 180, "",
      "mounting rotation IMU -> robot, [roll, pitch, yaw]",
      DEEPNAV_PARAM_FIELD(EkfConfig, q_robot_imu)},
    D{"p_imu_in_robot_m", ParamType::kVec3, "m", -10, 10, "",
      "IMU lever arm in the robot frame (FLU)",
      DEEPNAV_PARAM_FIELD(EkfConfig, p_imu_in_robot_m)},
    D{"dvl_rotation_deg", ParamType::kRotation, "deg", -180, 180, "",
      "mounting rotation DVL -> robot, [roll, pitch, yaw]",
      DEEPNAV_PARAM_FIELD(EkfConfig, q_robot_dvl)},
    D{"p_dvl_in_robot_m", ParamType::kVec3, "m", -10, 10, "",
      "DVL lever arm in the robot frame",
      DEEPNAV_PARAM_FIELD(EkfConfig, p_dvl_in_robot_m)},
    D{"p_depth_in_robot_m", ParamType::kVec3, "m", -10, 10, "",
      "pressure port position in the robot frame",
      DEEPNAV_PARAM_FIELD(EkfConfig, p_depth_in_robot_m)},
    D{"gyro_arw_radps_rthz", ParamType::kDouble, "rad/s/sqrt(Hz)", 1e-07, 1, "",
      "gyro angle random walk",
      DEEPNAV_PARAM_FIELD(EkfConfig, gyro_arw_radps_rthz)},
    D{"accel_vrw_mps2_rthz", ParamType::kDouble, "m/s^2/sqrt(Hz)", 1e-06, 10, "",
      "accelerometer velocity random walk",
      DEEPNAV_PARAM_FIELD(EkfConfig, accel_vrw_mps2_rthz)},
    D{"gyro_bias_rw_radps2_rthz", ParamType::kDouble, "rad/s^2/sqrt(Hz)", 0, 1, "",
      "gyro bias random walk",
      DEEPNAV_PARAM_FIELD(EkfConfig, gyro_bias_rw_radps2_rthz)},
    D{"accel_bias_rw_mps3_rthz", ParamType::kDouble, "m/s^3/sqrt(Hz)", 0, 10, "",
      "accelerometer bias random walk",
      DEEPNAV_PARAM_FIELD(EkfConfig, accel_bias_rw_mps3_rthz)},
    D{"gyro_bias_gm_tau_s", ParamType::kDouble, "s", 0, 1e6, "",
      "gyro bias as a first-order Gauss-Markov process of this correlation time, on top of the random walk (0: off; else >= 1)",
      DEEPNAV_PARAM_FIELD(EkfConfig, gyro_bias_gm_tau_s)},
    D{"gyro_bias_gm_sigma_radps", ParamType::kDouble, "rad/s", 0, 0.1, "",
      "steady-state 1-sigma of the gyro bias Gauss-Markov process (bias instability / 0.6174)",
      DEEPNAV_PARAM_FIELD(EkfConfig, gyro_bias_gm_sigma_radps)},
    D{"accel_bias_gm_tau_s", ParamType::kDouble, "s", 0, 1e6, "",
      "accelerometer bias Gauss-Markov correlation time (0: off; else >= 1)",
      DEEPNAV_PARAM_FIELD(EkfConfig, accel_bias_gm_tau_s)},
    D{"accel_bias_gm_sigma_mps2", ParamType::kDouble, "m/s^2", 0, 1, "",
      "steady-state 1-sigma of the accelerometer bias Gauss-Markov process",
      DEEPNAV_PARAM_FIELD(EkfConfig, accel_bias_gm_sigma_mps2)},
    D{"init_pos_sigma_m", ParamType::kDouble, "m", 0.0001, 10000.0, "",
      "initial position 1-sigma",
      DEEPNAV_PARAM_FIELD(EkfConfig, init_pos_sigma_m)},
    D{"init_vel_sigma_mps", ParamType::kDouble, "m/s", 0.0001, 100, "",
      "initial velocity 1-sigma",
      DEEPNAV_PARAM_FIELD(EkfConfig, init_vel_sigma_mps)},
    D{"init_yaw_sigma_rad", ParamType::kDouble, "rad", 0.0001, 3.5, "",
      "initial yaw 1-sigma (after the first heading)",
      DEEPNAV_PARAM_FIELD(EkfConfig, init_yaw_sigma_rad)},
    D{"dvl_sigma_mps", ParamType::kDouble, "m/s", 1e-05, 1, "",
      "DVL velocity 1-sigma per axis when the sample carries none",
      DEEPNAV_PARAM_FIELD(EkfConfig, dvl_sigma_mps)},
    D{"depth_sigma_m", ParamType::kDouble, "m", 0.0001, 10, "",
      "depth 1-sigma when the sample carries none",
      DEEPNAV_PARAM_FIELD(EkfConfig, depth_sigma_m)},
    D{"heading_sigma_rad", ParamType::kDouble, "rad", 0.0001, 1, "",
      "compass heading 1-sigma when the sample carries none",
      DEEPNAV_PARAM_FIELD(EkfConfig, heading_sigma_rad)},
    D{"attitude_sigma_rad", ParamType::kDouble, "rad", 1e-05, 1, "",
      "AHRS roll/pitch 1-sigma when the sample carries none",
      DEEPNAV_PARAM_FIELD(EkfConfig, attitude_sigma_rad)},
    D{"heading_sigma_floor_rad", ParamType::kDouble, "rad", 0, 1, "",
      "compass samples' 1-sigma raised to at least this (0: the sample's own)",
      DEEPNAV_PARAM_FIELD(EkfConfig, heading_sigma_floor_rad)},
    D{"dvl_scale_prior_sigma", ParamType::kDouble, "-", 0, 0.2, "",
      "prior 1-sigma of the estimated DVL scale factor, a fraction (0: not estimated)",
      DEEPNAV_PARAM_FIELD(EkfConfig, dvl_scale_prior_sigma)},
    D{"dvl_misalignment_prior_sigma_rad", ParamType::kDouble, "rad", 0, 0.2, "",
      "prior 1-sigma of each of the 3 estimated DVL misalignment angles (0: not estimated)",
      DEEPNAV_PARAM_FIELD(EkfConfig, dvl_misalignment_prior_sigma_rad)},
    D{"dvl_bias_prior_sigma_mps", ParamType::kDouble, "m/s", 0, 0.5, "",
      "prior 1-sigma of each of the 3 estimated DVL velocity biases, DVL axes (0: not estimated)",
      DEEPNAV_PARAM_FIELD(EkfConfig, dvl_bias_prior_sigma_mps)},
    D{"heading_bias_prior_sigma_rad", ParamType::kDouble, "rad", 0, 0.5, "",
      "prior 1-sigma of the estimated compass residual bias (0: not estimated)",
      DEEPNAV_PARAM_FIELD(EkfConfig, heading_bias_prior_sigma_rad)},
    D{"heading_deviation_prior_sigma_rad", ParamType::kDouble, "rad", 0, 0.5, "",
      "prior 1-sigma of each estimated compass deviation term B sin psi, C cos psi, D sin 2psi, E cos 2psi (0: not estimated)",
      DEEPNAV_PARAM_FIELD(EkfConfig, heading_deviation_prior_sigma_rad)},
    D{"magnetic_declination_rad", ParamType::kDouble, "rad", -3.15, 3.15, "",
      "true = magnetic + declination (east positive)",
      DEEPNAV_PARAM_FIELD(EkfConfig, magnetic_declination_rad)},
    D{"heading_bias_rad", ParamType::kDouble, "rad", -3.15, 3.15, "",
      "compass bias (measured = true + bias), e.g. hard iron",
      DEEPNAV_PARAM_FIELD(EkfConfig, heading_bias_rad)},
    D{"mag_disturbance_enabled", ParamType::kBool, "-", 0, 0, "",
      "watch the compass for magnetic disturbance (heading innovation offset while the yaw is held): de-weight, then refuse it, recover with hysteresis",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_enabled)},
    D{"mag_disturbance_tau_s", ParamType::kDouble, "s", 0.1, 600, "",
      "time constant of the low-passed normalised heading innovation",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_tau_s)},
    D{"mag_disturbance_suspect_sigma", ParamType::kDouble, "sigma", 0.1, 100, "",
      "low-passed normalised heading innovation above which the compass is de-weighted (> exit)",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_suspect_sigma)},
    D{"mag_disturbance_enter_sigma", ParamType::kDouble, "sigma", 0.1, 100, "",
      "above which the compass is refused (>= suspect)",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_enter_sigma)},
    D{"mag_disturbance_exit_sigma", ParamType::kDouble, "sigma", 0.01, 100, "",
      "below which, for exit_hold_s, the compass is trusted again",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_exit_sigma)},
    D{"mag_disturbance_exit_hold_s", ParamType::kDurationS, "s", 0, 600, "",
      "how long the innovations must stay consistent before the compass is trusted again",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_exit_hold_us)},
    D{"mag_disturbance_r_scale", ParamType::kDouble, "-", 1, 1e6, "",
      "compass variance factor while de-weighted",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_r_scale)},
    D{"mag_disturbance_yaw_held_ratio", ParamType::kDouble, "-", 0.001, 1000, "",
      "the compass is judged only while the predicted yaw variance H P H^T is below this times its variance R",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_yaw_held_ratio)},
    D{"mag_disturbance_aided_window_s", ParamType::kDurationS, "s", 0.01, 600, "",
      "the compass is judged only within this time of a fused marker pose (without one it is the only heading reference)",
      DEEPNAV_PARAM_FIELD(EkfConfig, mag_disturbance_aided_window_us)},
    D{"gate_dvl_sigma", ParamType::kDouble, "sigma", 1, 100, "",
      "DVL innovation gate",
      DEEPNAV_PARAM_FIELD(EkfConfig, gate_dvl_sigma)},
    D{"gate_depth_sigma", ParamType::kDouble, "sigma", 1, 100, "",
      "depth innovation gate",
      DEEPNAV_PARAM_FIELD(EkfConfig, gate_depth_sigma)},
    D{"gate_heading_sigma", ParamType::kDouble, "sigma", 1, 100, "",
      "compass innovation gate",
      DEEPNAV_PARAM_FIELD(EkfConfig, gate_heading_sigma)},
    D{"gate_attitude_sigma", ParamType::kDouble, "sigma", 1, 100, "",
      "AHRS innovation gate",
      DEEPNAV_PARAM_FIELD(EkfConfig, gate_attitude_sigma)},
    D{"gate_pose_sigma", ParamType::kDouble, "sigma", 1, 100, "",
      "marker pose innovation gate",
      DEEPNAV_PARAM_FIELD(EkfConfig, gate_pose_sigma)},
    D{"gate_relative_pose_sigma", ParamType::kDouble, "sigma", 1, 100, "",
      "visual odometry innovation gate",
      DEEPNAV_PARAM_FIELD(EkfConfig, gate_relative_pose_sigma)},
    D{"timeout_imu_s", ParamType::kDurationS, "s", 0, 10, "",
      "IMU stale after this long without a sample (0: not monitored)",
      DEEPNAV_PARAM_FIELD(EkfConfig, timeout_imu_us)},
    D{"timeout_dvl_s", ParamType::kDurationS, "s", 0, 60, "",
      "DVL stale timeout",
      DEEPNAV_PARAM_FIELD(EkfConfig, timeout_dvl_us)},
    D{"timeout_depth_s", ParamType::kDurationS, "s", 0, 60, "",
      "depth stale timeout",
      DEEPNAV_PARAM_FIELD(EkfConfig, timeout_depth_us)},
    D{"timeout_heading_s", ParamType::kDurationS, "s", 0, 60, "",
      "compass stale timeout",
      DEEPNAV_PARAM_FIELD(EkfConfig, timeout_heading_us)},
    D{"timeout_attitude_s", ParamType::kDurationS, "s", 0, 60, "",
      "AHRS stale timeout",
      DEEPNAV_PARAM_FIELD(EkfConfig, timeout_attitude_us)},
    D{"max_delay_s", ParamType::kDurationS, "s", 0.01, 2.0, "",
      "measurements older than this are dropped and counted; stamped this far ahead of the loop's clock, refused (a jumped clock)",
      DEEPNAV_PARAM_FIELD(EkfConfig, max_delay_us)},
    D{"history_imu_capacity", ParamType::kInt, "epochs", 8, 4096, "",
      "IMU epochs kept for re-propagation (cover max_delay at the IMU rate)",
      DEEPNAV_PARAM_FIELD(EkfConfig, history_imu_capacity)},
    D{"history_meas_capacity", ParamType::kInt, "measurements", 8, 4096, "",
      "measurements kept for re-fusion inside the window",
      DEEPNAV_PARAM_FIELD(EkfConfig, history_meas_capacity)},
    D{"align_imu_samples", ParamType::kInt, "samples", 1, 1000, "",
      "IMU samples averaged for the initial roll/pitch",
      DEEPNAV_PARAM_FIELD(EkfConfig, align_imu_samples)},
    D{"align_imu_only", ParamType::kBool, "-", 0, 0, "",
      "align from the IMU alone, yaw 0 and z 0 at the start, for a vehicle with no compass and no depth sensor "
      "(false: the alignment waits for both)",
      DEEPNAV_PARAM_FIELD(EkfConfig, align_imu_only)},
    D{"align_gyro_bias_at_rest", ParamType::kBool, "-", 0, 0, "",
      "the robot is at rest while aligning: the mean rate over the alignment samples is the initial gyro bias "
      "(false: it starts at 0)",
      DEEPNAV_PARAM_FIELD(EkfConfig, align_gyro_bias_at_rest)},
    D{"stuck_after_samples", ParamType::kInt, "samples", 0, 1000, "",
      "a DVL, depth, compass or AHRS sample bit-identical to the previous n-1 is refused as frozen (0: off; else >= 2)",
      DEEPNAV_PARAM_FIELD(EkfConfig, stuck_after_samples)},
    D{"imu_stuck_after_samples", ParamType::kInt, "samples", 0, 100000, "",
      "an IMU sample bit-identical (rates and specific force) to the previous n-1 is refused as frozen and the state coasts (0: off; else >= 2)",
      DEEPNAV_PARAM_FIELD(EkfConfig, imu_stuck_after_samples)},
    D{"gate_reset_after_s", ParamType::kDurationS, "s", 0, 60, "",
      "a DVL, depth, compass, AHRS or marker source rejected this long gets the states it observes reset to their initial sigmas (0: never)",
      DEEPNAV_PARAM_FIELD(EkfConfig, gate_reset_after_us)},
    D{"coast_accel_noise_mps2_rthz", ParamType::kDouble, "m/s^2/sqrt(Hz)", 0, 10, "",
      "IMU outage: the solution coasts on the last velocity, its covariance grown for a white acceleration of this density",
      DEEPNAV_PARAM_FIELD(EkfConfig, coast_accel_noise_mps2_rthz)},
};

bool fail(std::string* error, const char* key, const char* why) {
  if (error != nullptr) *error = std::string("EkfConfig.") + key + ": " + why;
  return false;
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }
bool bounds(double lo, double hi) { return positive(lo) && positive(hi) && lo < hi; }

// The fields no board key sets.
bool checkImu(const EkfConfig& c, std::string* e) {
  if (!positive(c.imu_max_rate_radps)) return fail(e, "imu_max_rate_radps", "must be > 0");
  if (!positive(c.imu_max_accel_mps2)) return fail(e, "imu_max_accel_mps2", "must be > 0");
  if (c.imu_max_gap_us <= 0) return fail(e, "imu_max_gap_us", "must be > 0");
  return true;
}

bool checkInitial(const EkfConfig& c, std::string* e) {
  if (!positive(c.init_roll_pitch_sigma_rad)) return fail(e, "init_roll_pitch_sigma_rad", "must be > 0");
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

// Rules between fields, which a range per key cannot say.
bool checkMagDisturbance(const EkfConfig& c, std::string* e) {
  if (!(c.mag_disturbance_suspect_sigma > c.mag_disturbance_exit_sigma)) {
    return fail(e, "mag_disturbance_suspect_sigma", "must be > mag_disturbance_exit_sigma");
  }
  if (!(c.mag_disturbance_enter_sigma >= c.mag_disturbance_suspect_sigma)) {
    return fail(e, "mag_disturbance_enter_sigma", "must be >= mag_disturbance_suspect_sigma");
  }
  return true;
}

bool checkSystematic(const EkfConfig& c, std::string* e) {
  // 0 switches the Gauss-Markov process off; an active one needs tau >= 1 s (ekf.gyro_bias_gm_tau_s's meaning).
  if (c.gyro_bias_gm_tau_s != 0.0 && c.gyro_bias_gm_tau_s < 1.0) {
    return fail(e, "gyro_bias_gm_tau_s", "must be 0 (off) or in [1, 1e6] s");
  }
  if (c.accel_bias_gm_tau_s != 0.0 && c.accel_bias_gm_tau_s < 1.0) {
    return fail(e, "accel_bias_gm_tau_s", "must be 0 (off) or in [1, 1e6] s");
  }
  return true;
}

bool checkTiming(const EkfConfig& c, std::string* e) {
  if (c.timeout_markers_us < 0) return fail(e, "timeout_markers_us", "must be >= 0");
  if (c.timeout_vo_us < 0) return fail(e, "timeout_vo_us", "must be >= 0");
  if (c.position_aided_timeout_us < 0) return fail(e, "position_aided_timeout_us", "must be >= 0");
  if (c.max_clones < 1 || c.max_clones > es::kMaxClones) return fail(e, "max_clones", "must be in [1, es::kMaxClones]");
  // 1 would refuse every sample (each is bit-identical to "the previous 0").
  if (c.imu_stuck_after_samples == 1) return fail(e, "imu_stuck_after_samples", "must be 0 (off) or >= 2");
  if (c.stuck_after_samples == 1) return fail(e, "stuck_after_samples", "must be 0 (off) or >= 2");
  return true;
}

}  // namespace

std::span<const ParamDecl<EkfConfig>> ekfParams() { return kEkfParams; }

bool validateEkfConfig(const EkfConfig& config, std::string* error) {
  return checkParamRanges(ekfParams(), config, "EkfConfig", kEkfSection, error) && checkImu(config, error) &&
         checkInitial(config, error) && checkBounds(config, error) && checkMagDisturbance(config, error) &&
         checkSystematic(config, error) && checkTiming(config, error);
}

}  // namespace deepnav
