#pragma once
#include <cstdint>
#include <span>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "base/param_decl.h"
#include "nav/types/time.h"

namespace deepnav {

// Every parameter of the error-state EKF, with its unit in its name and its default here (the one place
// it is declared). Frames: odometry O is ENU (z up), robot R is FLU. The fields a board sets are declared
// with key, unit and range in ekfParams() (ekf_config.cpp); validateEkfConfig() checks those ranges and
// the rules between fields.
struct EkfConfig {
  // --- Physics --------------------------------------------------------------------------------------
  double gravity_mps2 = 9.80665;  // magnitude of gravity along -z of odom

  // --- Mounting (board geometry) ----------------------------------------------------------------------
  Eigen::Quaterniond q_robot_imu = Eigen::Quaterniond::Identity();  // rotation IMU -> robot
  Eigen::Vector3d p_imu_in_robot_m = Eigen::Vector3d::Zero();       // IMU lever arm, robot frame
  Eigen::Quaterniond q_robot_dvl = Eigen::Quaterniond::Identity();  // rotation DVL -> robot
  Eigen::Vector3d p_dvl_in_robot_m = Eigen::Vector3d::Zero();       // DVL lever arm, robot frame
  Eigen::Vector3d p_depth_in_robot_m = Eigen::Vector3d::Zero();     // pressure port, robot frame

  // --- IMU noise (continuous-time densities) ------------------------------------------------------------
  double gyro_arw_radps_rthz = 1.0e-4;        // angle random walk, rad/s/sqrt(Hz)
  double accel_vrw_mps2_rthz = 1.0e-3;        // velocity random walk, m/s^2/sqrt(Hz)
  double gyro_bias_rw_radps2_rthz = 1.0e-5;   // gyro bias random walk, rad/s^2/sqrt(Hz)
  double accel_bias_rw_mps3_rthz = 1.0e-4;    // accel bias random walk, m/s^3/sqrt(Hz)

  // --- IMU input sanity -----------------------------------------------------------------------------
  double imu_max_rate_radps = 35.0;     // |w| above this is bad input (2000 deg/s)
  double imu_max_accel_mps2 = 160.0;    // |f| above this is bad input (16 g)
  TimeUs imu_max_gap_us = 100'000;      // a longer IMU gap is still propagated but counted

  // --- Initial uncertainty (1-sigma) ---------------------------------------------------------------------
  double init_pos_sigma_m = 0.1;               // x, y (and z before the depth correction)
  double init_vel_sigma_mps = 0.1;
  double init_roll_pitch_sigma_rad = 0.02;
  double init_yaw_sigma_rad = 0.1;
  double init_gyro_bias_sigma_radps = 1.0e-3;
  double init_accel_bias_sigma_mps2 = 0.05;

  // --- Variance bounds, applied after every step (max keeps the filter responsive, min keeps P PD) ---
  double pos_var_min_m2 = 1.0e-12;
  double pos_var_max_m2 = 1.0e6;
  double vel_var_min_m2ps2 = 1.0e-12;
  double vel_var_max_m2ps2 = 1.0e4;
  double angle_var_min_rad2 = 1.0e-14;
  double angle_var_max_rad2 = 10.0;
  double gyro_bias_var_min_rad2ps2 = 1.0e-16;
  double gyro_bias_var_max_rad2ps2 = 1.0e-2;
  double accel_bias_var_min_m2ps4 = 1.0e-14;
  double accel_bias_var_max_m2ps4 = 1.0;

  // --- Measurement defaults (used when a sample carries sigma 0 / covariance 0) -------------------------
  double dvl_sigma_mps = 0.01;           // per axis, when the sample has neither covariance nor FOM
  double depth_sigma_m = 0.05;
  double heading_sigma_rad = 0.035;      // about 2 deg
  double attitude_sigma_rad = 0.0087;    // about 0.5 deg, roll and pitch

  // --- Compass -----------------------------------------------------------------------------------------
  double magnetic_declination_rad = 0.0;  // true = magnetic + declination (east positive)
  double heading_bias_rad = 0.0;          // measured = true + bias; subtracted before fusion

  // --- Magnetic disturbance (mag_disturbance.h): off by default --------------------------------------
  bool mag_disturbance_enabled = false;
  double mag_disturbance_tau_s = 3.0;          // low-pass time constant of the normalised innovation
  double mag_disturbance_suspect_sigma = 1.0;  // |mean| above: compass de-weighted (R x r_scale)
  double mag_disturbance_enter_sigma = 2.0;    // |mean| above: compass refused; >= suspect
  double mag_disturbance_exit_sigma = 0.5;     // |mean| below this for exit_hold: clean again; < suspect
  TimeUs mag_disturbance_exit_hold_us = 3'000'000;
  double mag_disturbance_r_scale = 25.0;       // compass variance factor while suspect
  double mag_disturbance_yaw_held_ratio = 1.0; // judged only while H P H^T < this x R (yaw held)
  TimeUs mag_disturbance_aided_window_us = 2'000'000;  // ... and a marker pose was fused this recently

  // --- Systematic error states (systematic_states.h): a prior 1-sigma of 0 leaves the state out -------
  double dvl_scale_prior_sigma = 0.0;              // DVL scale factor s (v_meas = (1 + s) v), fraction
  double dvl_misalignment_prior_sigma_rad = 0.0;   // DVL mounting rotation, each of 3 axes, rad
  double dvl_bias_prior_sigma_mps = 0.0;           // DVL velocity bias, each of 3 DVL axes, m/s
  double heading_bias_prior_sigma_rad = 0.0;       // compass residual bias, rad
  double heading_deviation_prior_sigma_rad = 0.0;  // each of the deviation terms B, C, D, E, rad
  // Compass samples' sigma raised to at least this (their white noise may be far below the datasheet's
  // accuracy); 0: the sample's own sigma.
  double heading_sigma_floor_rad = 0.0;

  // --- IMU biases as first-order Gauss-Markov processes (bias_gauss_markov.h); tau 0: random walk only ---
  double gyro_bias_gm_tau_s = 0.0;         // correlation time T_c, s, 0 (off) or >= 1
  double gyro_bias_gm_sigma_radps = 0.0;   // steady-state 1-sigma (bias instability / 0.6174)
  double accel_bias_gm_tau_s = 0.0;
  double accel_bias_gm_sigma_mps2 = 0.0;

  // --- Innovation gates, in sigma: ratio = innov^2 / (gate^2 S) for one dof; for n dof see
  //     innovation_gate.h (chi-square quantile of the same tail probability + per-axis test) ---------
  double gate_dvl_sigma = 3.0;
  double gate_depth_sigma = 3.0;
  double gate_heading_sigma = 3.0;
  double gate_attitude_sigma = 3.0;
  double gate_pose_sigma = 3.0;
  double gate_relative_pose_sigma = 3.0;

  // --- Timeouts: a source with no accepted sample for this long is stale; 0 = not monitored ----------
  TimeUs timeout_imu_us = 50'000;
  TimeUs timeout_dvl_us = 1'000'000;
  TimeUs timeout_depth_us = 1'000'000;
  TimeUs timeout_heading_us = 1'000'000;
  TimeUs timeout_attitude_us = 1'000'000;
  TimeUs timeout_markers_us = 0;   // markers are seen only near the panel
  TimeUs timeout_vo_us = 0;        // both VO sources (ORB and planes)
  TimeUs position_aided_timeout_us = 2'000'000;  // kStatusPositionValid while a pose/VO fused this recently

  // --- Faulty streams (tests/integration/fault_sensors_test.cpp) -----------------------------------------
  // A DVL, depth, compass or AHRS sample bit-identical to the previous `stuck_after_samples` - 1 of its
  // source is refused as frozen (a real sensor's noise never repeats every bit; a quantised one at rest
  // may, and then refusing a value the filter already has loses nothing); 0: not checked.
  int stuck_after_samples = 5;
  // The same for the IMU, whose six channels of noise (rate and specific force) never repeat together
  // on a working unit: refused, the IMU goes stale and the state coasts as in an IMU outage. 0 (the
  // bare filter's default, whose tests feed a noiseless resting IMU): not checked; boards set it.
  int imu_stuck_after_samples = 0;
  // A DVL, depth, compass, AHRS or marker source whose samples have all been rejected for this long (a gate
  // lockout: the state drifted away while the filter grew overconfident) gets the states it observes
  // decorrelated and their variances raised to the initial sigmas, once per period, so that the gate
  // can let it back in; 0: never.
  TimeUs gate_reset_after_us = 2'000'000;
  // IMU outage (no IMU sample for longer than timeout_imu_us, or a gap over imu_max_gap_us): nothing
  // propagates the state, so the solution (ekf_solution.cpp) and then the state (imu_gap_bridge.h) coast
  // on the last velocity, their covariance grown for a white acceleration of this density
  // (nearly-constant-velocity model), m/s^2/sqrt(Hz).
  double coast_accel_noise_mps2_rthz = 0.1;

  // --- Delayed fusion -----------------------------------------------------------------------------------
  TimeUs max_delay_us = 500'000;       // measurements older than now - this are dropped and counted
  int history_imu_capacity = 160;      // snapshots kept; must cover max_delay at the IMU rate (+2)
  int history_meas_capacity = 128;     // measurements kept for re-fusion inside the window

  // --- Stochastic clones -------------------------------------------------------------------------------
  int max_clones = 4;                  // [1, es::kMaxClones]

  // --- Initial alignment ----------------------------------------------------------------------------
  int align_imu_samples = 20;          // IMU samples averaged for roll/pitch from gravity
  // A vehicle with no compass and no depth sensor (a MAV dataset): align from the IMU alone, yaw 0 and
  // z 0 at the start unless a compass or depth sample came first. Off: alignment waits for both.
  bool align_imu_only = false;
  // The robot is at rest while aligning: the mean rate over those samples is the initial gyro bias
  // (Earth's 7.3e-5 rad/s included). Off: the bias starts at 0.
  bool align_gyro_bias_at_rest = false;
};

// The board keys of the filter (section kEkfSection of a board file): key, unit, range and meaning of each
// field a board sets, declared once; the defaults are the initialisers above.
inline constexpr const char* kEkfSection = "ekf";
std::span<const ParamDecl<EkfConfig>> ekfParams();

// Checks every field; on failure writes a message naming the field (and its board key) and returns false.
bool validateEkfConfig(const EkfConfig& config, std::string* error);

}  // namespace deepnav
