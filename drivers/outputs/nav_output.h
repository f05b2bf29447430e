#pragma once
#include <cstdint>

#include "nav/types/nav_solution.h"

namespace deepnav {

// Service-level health bits, each about the last health window (about half a second): what the vehicle
// and the topside are told besides the estimator's own status and fault bits.
enum NavHealthBits : std::uint32_t {
  kHealthLoopStalled = 1u << 0,     // no nav tick in the window (the systemd watchdog is not fed)
  kHealthLoopLate = 1u << 1,        // some ticks started late
  kHealthNavOverrun = 1u << 2,      // some nav ticks exceeded loop.budget_us
  kHealthVisionOverrun = 1u << 3,   // some stereo pairs exceeded loop.vision_budget_us
  kHealthRecorderDrops = 1u << 4,   // the recorder queue refused records
  kHealthRecordingFailed = 1u << 5, // the recording cannot be written
  kHealthInputsRefused = 1u << 6,   // a driver outran the loop (full input ring or frame pool)
  kHealthSensorStale = 1u << 7,     // some source timed out (see the fault bits)
  kHealthSensorRejected = 1u << 8,  // some source's last measurement was gated out
  kHealthNotFinite = 1u << 9,       // the solution holds a non-finite number (never expected)
  kHealthVisionFailed = 1u << 10,   // a vision stage threw on some stereo pairs (skipped, nothing fused)
};

// Counters carried by every output (cumulative since start).
struct NavCounters {
  std::uint64_t ticks = 0, late_ticks = 0, nav_overruns = 0, vision_overruns = 0;
  std::uint64_t recorder_drops = 0, inputs_refused = 0;
  std::uint64_t imu = 0, dvl = 0, depth = 0, heading = 0, attitude = 0, vision = 0;  // samples consumed
};

// One tick's output to the vehicle: the solution, its tick sequence number, health bits and counters.
struct NavOutput {
  std::uint32_t sequence = 0;
  NavSolution solution;
  std::uint32_t health = 0;  // NavHealthBits
  NavCounters counters;
};

// Euler angles [roll, pitch, yaw] (ZYX, radians) of q_odom_robot; yaw is ENU (counter-clockwise from east).
void eulerZyxRad(const Eigen::Quaterniond& q, double* roll_rad, double* pitch_rad, double* yaw_rad);

}  // namespace deepnav
