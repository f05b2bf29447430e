#pragma once
#include <cstdint>
#include <string>

#include "nav/types/attitude_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"
#include "tools/sim/sensors/attitude_grades.h"

namespace deepnav::sim {

// Scenario key `attitude`: an AHRS giving roll and pitch (ZYX Euler angles of q_odom_robot).
struct AttitudeConfig {
  AttitudeGrade grade = AttitudeGrade::kNone;  // attitude_grades.h; applied by the loader before the keys
  bool enabled = true;
  double rate_hz = 10.0;
  double noise_deg = 0.1;       // 1-sigma white noise on roll and on pitch
  double roll_bias_deg = 0.0;   // fixed bias, added to roll
  double pitch_bias_deg = 0.0;  // fixed bias, added to pitch
  double bias_sigma_deg = 0.0;  // 1-sigma of a per-dive bias drawn per axis (per seed), added as well

  bool operator==(const AttitudeConfig&) const = default;
};

// roll = true roll + roll bias + noise, pitch likewise; the biases are fixed for a dive.
class AttitudeModel {
 public:
  bool init(const AttitudeConfig& config, std::uint64_t seed, std::string* error);
  AttitudeSample measure(const KinematicState& truth, TimeUs t_us);
  double noiseSigma_rad() const;
  // This dive's biases (fixed + drawn), rad.
  double rollBias_rad() const { return roll_bias_rad_; }
  double pitchBias_rad() const { return pitch_bias_rad_; }

 private:
  AttitudeConfig config_;
  NormalRng rng_;
  bool biased_ = false;
  double roll_bias_rad_ = 0.0;
  double pitch_bias_rad_ = 0.0;
};

}  // namespace deepnav::sim
