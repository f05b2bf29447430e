#pragma once
#include <Eigen/Geometry>

#include "drivers/euroc/euroc_streams.h"
#include "nav/types/imu_sample.h"
#include "nav/types/truth_sample.h"
#include "nav/types/time.h"

namespace deepnav {

// The EuRoC body frame B (= the ADIS16448 IMU frame, imu0 T_BS = identity) has x up, y right and z forward,
// the direction the cameras look: cam0's T_BS maps the optical axis to +z_B (0.004, 0.026, 1.000) and the
// image's down to -x_B, and at rest the accelerometer reads +9.1 m/s2 along x_B. deepnav's robot frame R
// is FLU (REP-103) with its origin at B's: forward = z_B, left = -y_B, up = x_B, so
//   R_robot_body = [0 0 1; 0 -1 0; 1 0 0]   (det +1), p_R = R_robot_body p_B.
Eigen::Matrix3d eurocRobotFromBody();

// deepnav time of an EuRoC timestamp: microseconds since t0_ns (the first sample of the folder), rounded.
TimeUs eurocTimeUs(std::int64_t t_ns, std::int64_t t0_ns);

// An imu0 row as an ImuSample in the robot frame: w_R = R_robot_body R_body_sensor w_S, the same for the
// specific force (the IMU sits at the body origin in EuRoC; a lever arm is the board's ekf.p_imu_in_robot_m).
ImuSample eurocImuSample(const EurocImuRow& row, const Eigen::Matrix3d& R_body_sensor, std::int64_t t0_ns);

// A ground-truth row as a TruthSample: the robot frame in the Vicon world frame (z up, taken as the
// recording's odometry frame), q_world_robot = q_world_body R_robot_body^T. The rate is not in the file (0).
TruthSample eurocTruthSample(const EurocTruthRow& row, std::int64_t t0_ns);

}  // namespace deepnav
