#pragma once
#include <array>
#include <cstdint>

#include "nav/types/dvl_sample.h"

namespace deepnav {

// A Water Linked DVL (A50/A125) report, from either protocol (serial "wr?" sentences or TCP JSON v3).
// Units: m/s, m, s; times of validity and transmission in microseconds (DVL clock, Unix epoch).
// The DVL frame is x forward, y right, z down.
struct WlDvlReport {
  enum class Kind { kVelocity, kTransducer, kDeadReckoning };
  Kind kind = Kind::kVelocity;
  // Velocity report (serial "wrz", JSON "velocity").
  double vx_mps = 0, vy_mps = 0, vz_mps = 0;
  bool velocity_valid = false;
  double altitude_m = 0;
  double fom_mps = 0;
  std::array<double, 9> covariance_m2ps2{};  // row-major
  bool has_covariance = false;
  int64_t time_of_validity_us = 0;
  int64_t time_of_transmission_us = 0;
  double time_since_last_ms = 0;  // "time": milliseconds since the previous report
  int status = 0;                 // 0 = normal
  // Per-transducer data (JSON "transducers", or one serial "wru" sentence in slot 0).
  struct Transducer {
    int id = 0;
    double velocity_mps = 0;
    double distance_m = 0;
    double rssi_dbm = 0;
    double nsd_dbm = 0;
    bool beam_valid = false;
  };
  std::array<Transducer, 4> transducers{};
  int num_transducers = 0;
  // Dead-reckoning report (serial "wrp", JSON "position_local").
  double ts_s = 0;
  double x_m = 0, y_m = 0, z_m = 0, pos_std_m = 0;
  double roll_rad = 0, pitch_rad = 0, yaw_rad = 0;
};

// Velocity report as a DvlSample in FLU: (x, -y, -z). Covariance rotated the same way.
bool dvlSampleFromWlReport(const WlDvlReport& report, TimeUs t_us, DvlSample* sample);

}  // namespace deepnav
