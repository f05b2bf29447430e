#pragma once
#include <cstdint>
#include <string>

#include "nav/types/attitude_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// Scenario key `attitude`: an AHRS giving roll and pitch (ZYX Euler angles of q_odom_robot).
struct AttitudeConfig {
  bool enabled = true;
  double rate_hz = 10.0;
  double noise_deg = 0.1;  // 1-sigma white noise on roll and on pitch

  bool operator==(const AttitudeConfig&) const = default;
};

class AttitudeModel {
 public:
  bool init(const AttitudeConfig& config, std::uint64_t seed, std::string* error);
  AttitudeSample measure(const KinematicState& truth, TimeUs t_us);
  double noiseSigma_rad() const;

 private:
  AttitudeConfig config_;
  NormalRng rng_;
};

}  // namespace deepnav::sim
