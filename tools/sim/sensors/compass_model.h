#pragma once
#include <cstdint>
#include <string>

#include "nav/types/heading_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// Scenario key `compass`.
struct CompassConfig {
  bool enabled = true;
  double rate_hz = 10.0;
  double noise_deg = 0.3;        // 1-sigma white noise
  double bias_deg = 2.0;         // constant hard-iron offset, added to the heading
  double declination_deg = 0.0;  // magnetic declination, east positive (ignored when true_north)
  bool true_north = false;       // a gyrocompass: no declination, HeadingSample::is_true set

  bool operator==(const CompassConfig&) const = default;
};

// Heading clockwise from north in [0, 2 pi). With declination D (east positive, the usual sign), a
// magnetic compass reads the magnetic heading, true heading - D:
//   heading = (pi/2 - yaw_enu) - D + bias + noise,
// so the consumer recovers the true heading as heading + D - bias.
class CompassModel {
 public:
  bool init(const CompassConfig& config, std::uint64_t seed, std::string* error);
  HeadingSample measure(const KinematicState& truth, TimeUs t_us);
  // Heading without noise (bias and declination included).
  double noiselessHeading_rad(const KinematicState& truth) const;
  double noiseSigma_rad() const;

 private:
  CompassConfig config_;
  NormalRng rng_;
};

}  // namespace deepnav::sim
