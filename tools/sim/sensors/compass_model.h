#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "nav/types/heading_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"
#include "tools/sim/panel_geometry.h"
#include "tools/sim/sensors/compass_deviation.h"
#include "tools/sim/sensors/compass_grades.h"
#include "tools/sim/sensors/panel_magnetic_field.h"

namespace deepnav::sim {

// Scenario key `compass`.
struct CompassConfig {
  CompassGrade grade = CompassGrade::kNone;  // compass_grades.h; applied by the loader before the keys
  bool enabled = true;
  double rate_hz = 10.0;
  double noise_deg = 0.3;        // 1-sigma white noise
  double bias_deg = 2.0;         // constant hard-iron offset, added to the heading (the board knows it)
  double declination_deg = 0.0;  // magnetic declination, east positive (ignored when true_north)
  bool true_north = false;       // a gyrocompass: no declination, HeadingSample::is_true set
  // Errors the board does not know about (all zero: off).
  double residual_bias_deg = 0.0;        // fixed, added to the heading
  double residual_bias_sigma_deg = 0.0;  // 1-sigma, one draw per dive (per seed), added as well
  CompassDeviation deviation;            // heading-dependent hard/soft-iron deviation (magnetic only)
  // The panel's magnetic disturbance (magnetic only): off while panel_magnet is all zero.
  std::array<double, 3> p_compass_in_robot_m{0.0, 0.0, 0.0};
  double earth_horizontal_field_ut = 20.0;
  double earth_vertical_field_ut = 40.0;  // positive down (northern hemisphere)
  PanelMagnetConfig panel_magnet;

  bool magneticErrorsActive() const { return !deviation.isZero() || panel_magnet.active(); }
  bool operator==(const CompassConfig&) const = default;
};

// Heading clockwise from north in [0, 2 pi). With declination D (east positive, the usual sign), a
// magnetic compass reads the magnetic heading, true heading - D:
//   heading = (pi/2 - yaw_enu) - D + bias + noise,
// so the consumer recovers the true heading as heading + D - bias. With the errors the board does not
// know, a magnetic compass reads
//   psi = (pi/2 - yaw_enu) - D + e_panel(p)      (the heading of the disturbed horizontal field)
//   heading = psi + delta(psi) + bias + residual + noise,
// e_panel from the vector sum of the Earth's and the panel's field at the compass (panel_magnetic_field.h),
// delta the deviation series (compass_deviation.h).
class CompassModel {
 public:
  // panel and seabed_z_in_odom_m place the panel's dipole (used only when config.panel_magnet is active).
  bool init(const CompassConfig& config, const PanelGeometry& panel, double seabed_z_in_odom_m, std::uint64_t seed,
            std::string* error);
  HeadingSample measure(const KinematicState& truth, TimeUs t_us);
  // Heading without noise (bias, residual, deviation, panel field and declination included).
  double noiselessHeading_rad(const KinematicState& truth) const;
  double noiseSigma_rad() const;
  // The panel's heading error at the compass for this state (0 when the disturbance is off).
  double panelHeadingError_rad(const KinematicState& truth) const;
  // The residual bias of this dive: residual_bias_deg + its draw, in rad.
  double residualBias_rad() const { return residual_bias_rad_; }

 private:
  CompassConfig config_;
  NormalRng rng_;
  double residual_bias_rad_ = 0.0;
  EarthField earth_;
  PanelMagneticField panel_field_;
};

}  // namespace deepnav::sim
