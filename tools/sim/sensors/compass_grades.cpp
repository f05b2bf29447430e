#include "tools/sim/sensors/compass_grades.h"

#include "tools/sim/sensors/compass_model.h"

namespace deepnav::sim {

namespace {

struct CompassGradeTable {
  double noise_deg;                // white noise: the datasheet's repeatability / resolution
  double residual_bias_sigma_deg;  // per-dive residual after calibration: the datasheet's heading accuracy
  bool true_north;
};

// tools/sim/README.md "Compass, attitude and depth errors" cites each figure.
CompassGradeTable table(CompassGrade grade) {
  switch (grade) {
    case CompassGrade::kFluxgate:
      return {0.05, 0.3, false};  // PNI TCM XB: repeatability 0.05 deg, accuracy 0.3 deg rms
    case CompassGrade::kAhrsMems:
      return {0.05, 1.0, false};  // Xsens MTi-30: resolution 0.05 deg, yaw 1.0 deg (typ)
    case CompassGrade::kGyrocompass:
      return {0.01, 0.14, true};  // iXblue Octans: resolution 0.01 deg, 0.1 deg sec(lat) at 43 N
    case CompassGrade::kNone:
      break;
  }
  return {};
}

}  // namespace

const std::vector<std::string>& compassGradeNames() {
  static const std::vector<std::string> names{"fluxgate", "ahrs_mems", "gyrocompass"};
  return names;
}

void applyCompassGrade(CompassGrade grade, CompassConfig* config) {
  config->grade = grade;
  if (grade == CompassGrade::kNone) return;
  const CompassGradeTable t = table(grade);
  config->noise_deg = t.noise_deg;
  config->residual_bias_sigma_deg = t.residual_bias_sigma_deg;
  config->true_north = t.true_north;
}

}  // namespace deepnav::sim
