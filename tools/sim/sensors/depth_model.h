#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "nav/types/depth_sample.h"
#include "tools/sim/environment_config.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"
#include "tools/sim/sensors/depth_grades.h"

namespace deepnav::sim {

// Scenario key `depth`.
struct DepthConfig {
  DepthGrade grade = DepthGrade::kNone;  // depth_grades.h; applied by the loader before the keys
  bool enabled = true;
  double rate_hz = 10.0;
  double noise_m = 0.02;                                   // 1-sigma, as depth (converted to pascal)
  std::array<double, 3> p_sensor_in_robot_m{0.0, 0.0, 0.0};  // lever arm of the pressure port
  double resolution_pa = 0.0;         // quantisation step of the absolute pressure; 0: none
  double density_error_kgpm3 = 0.0;   // true mean water-column density - the nominal (environment) one
  double drift_m_per_h = 0.0;         // linear drift from t = 0, as depth (converted to pascal)

  bool operator==(const DepthConfig&) const = default;
};

// Pressure sensor: pressure_pa = p_atm + rho g depth + noise; depth_m is what the driver computes back
// from it with the same constants, so depth_m carries the same noise in metres. With the errors on:
//   pressure_pa = Q(p_atm + rho_true g depth + rho g drift_m_per_h t_h + noise),  Q: rounding to resolution_pa,
//   depth_m = (pressure_pa - p_atm) / (rho g),   rho the nominal density (environment.water_density_kgpm3),
// so the depth reads (rho_true / rho) times the true depth: a scale factor error.
class DepthModel {
 public:
  bool init(const DepthConfig& config, const EnvironmentConfig& environment, std::uint64_t seed,
            std::string* error);
  DepthSample measure(const KinematicState& truth, TimeUs t_us);
  double trueDepth_m(const KinematicState& truth) const;
  double noiseSigma_pa() const;
  // Depth scale factor rho_true / rho (1 without a density error).
  double scaleFactor() const;

 private:
  DepthConfig config_;
  EnvironmentConfig environment_;
  NormalRng rng_;
  bool extra_errors_ = false;
};

}  // namespace deepnav::sim
