#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "nav/types/depth_sample.h"
#include "tools/sim/environment_config.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// Scenario key `depth`.
struct DepthConfig {
  bool enabled = true;
  double rate_hz = 10.0;
  double noise_m = 0.02;                                   // 1-sigma, as depth (converted to pascal)
  std::array<double, 3> p_sensor_in_robot_m{0.0, 0.0, 0.0};  // lever arm of the pressure port

  bool operator==(const DepthConfig&) const = default;
};

// Pressure sensor: pressure_pa = p_atm + rho g depth + noise; depth_m is what the driver computes back
// from it with the same constants, so depth_m carries the same noise in metres.
class DepthModel {
 public:
  bool init(const DepthConfig& config, const EnvironmentConfig& environment, std::uint64_t seed,
            std::string* error);
  DepthSample measure(const KinematicState& truth, TimeUs t_us);
  double trueDepth_m(const KinematicState& truth) const;
  double noiseSigma_pa() const;

 private:
  DepthConfig config_;
  EnvironmentConfig environment_;
  NormalRng rng_;
};

}  // namespace deepnav::sim
