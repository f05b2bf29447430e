#pragma once
#include <string>
#include <vector>

namespace deepnav::sim {

struct DvlConfig;

// Scenario key `dvl.grade`: a named instrument whose datasheet figures set the DVL's error terms
// (tools/sim/README.md, "DVL grades", cites each figure). kNone keeps the built-in model untouched.
enum class DvlGrade { kNone = 0, kCompact, kStandard, kPrecision };

// The grade names in enum order, as written in scenario files: none, compact, standard, precision.
const std::vector<std::string>& dvlGradeNames();

// One instrument's datasheet figures.
struct DvlGradeSpec {
  const char* instrument;
  double long_term_percent;            // long-term accuracy: +-(percent of velocity ...
  double long_term_constant_mps;       // ... + constant)
  double ping_sigma_horizontal_mps;    // per-ping 1-sigma of a horizontal component, at 1 m/s
  double min_altitude_m;
  double max_altitude_m;
  double max_ping_rate_hz;
};

const DvlGradeSpec& dvlGradeSpec(DvlGrade grade);  // grade != kNone

// Sets every parameter the grade covers; the caller then reads the explicit keys, which override. The
// long-term accuracy becomes a per-dive scale factor (its percent part, as a 1-sigma) and a per-dive
// velocity bias per axis (its constant part); the per-ping figure becomes the per-beam noise floor; the
// built-in per-axis noise is turned off (the beams carry the noise); the channel runs at the maximum
// ping rate and the instrument pings as fast as its altitude allows.
void applyDvlGrade(DvlGrade grade, DvlConfig* config);

}  // namespace deepnav::sim
