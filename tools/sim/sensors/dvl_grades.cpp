#include "tools/sim/sensors/dvl_grades.h"

#include <array>
#include <cmath>

#include "tools/sim/rotation.h"
#include "tools/sim/sensors/dvl_model.h"

namespace deepnav::sim {

namespace {

// Figures and their sources: tools/sim/README.md, "DVL grades".
constexpr std::array<DvlGradeSpec, 3> kSpecs{{
    {"Water Linked DVL A50 (standard edition)", 1.01, 0.001, 0.006, 0.05, 50.0, 26.0},
    {"Teledyne RDI Pathfinder 600 kHz", 0.4, 0.002, 0.006, 0.3, 89.0, 10.0},
    {"Teledyne RDI Workhorse Navigator 600 kHz", 0.2, 0.001, 0.003, 0.7, 90.0, 7.0},
}};

// The three instruments are Janus arrays with beams 30 deg from vertical.
constexpr double kDatasheetBeamAngle_deg = 30.0;

}  // namespace

const std::vector<std::string>& dvlGradeNames() {
  static const std::vector<std::string> names{"none", "compact", "standard", "precision"};
  return names;
}

const DvlGradeSpec& dvlGradeSpec(DvlGrade grade) { return kSpecs[static_cast<int>(grade) - 1]; }

void applyDvlGrade(DvlGrade grade, DvlConfig* c) {
  c->grade = grade;
  if (grade == DvlGrade::kNone) return;
  const DvlGradeSpec& g = dvlGradeSpec(grade);
  c->noise_fraction_of_speed = 0.0;
  c->noise_floor_mps = 0.0;
  // A 4-beam Janus solution has horizontal variance sigma_beam^2 / (2 sin^2 a) (dvl_beam_solver.h), so a
  // datasheet's horizontal per-ping sigma is a per-beam sigma of sqrt(2) sin(a) times it.
  c->beam_noise_fraction = 0.0;
  c->beam_noise_floor_mps = g.ping_sigma_horizontal_mps * std::sqrt(2.0) * std::sin(kDatasheetBeamAngle_deg * kDegToRad);
  c->scale_factor_sigma_percent = g.long_term_percent;
  c->bias_sigma_mps = g.long_term_constant_mps;
  c->min_altitude_m = g.min_altitude_m;
  c->max_altitude_m = g.max_altitude_m;
  c->rate_hz = g.max_ping_rate_hz;
  c->max_ping_rate_hz = g.max_ping_rate_hz;
}

}  // namespace deepnav::sim
