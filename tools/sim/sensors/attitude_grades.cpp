#include "tools/sim/sensors/attitude_grades.h"

#include "tools/sim/sensors/attitude_model.h"

namespace deepnav::sim {

namespace {

struct AttitudeGradeTable {
  double noise_deg;       // white noise per sample
  double bias_sigma_deg;  // per-dive bias per axis: the datasheet's static accuracy
};

// tools/sim/README.md "Compass, attitude and depth errors" cites each figure.
AttitudeGradeTable table(AttitudeGrade grade) {
  switch (grade) {
    case AttitudeGrade::kFluxgate:
      return {0.01, 0.2};  // PNI TCM XB: pitch/roll resolution 0.01 deg, accuracy 0.2 deg rms
    case AttitudeGrade::kAhrsMems:
      return {0.46, 0.2};  // Xsens MTi-30: static 0.2 deg, dynamic 0.5 deg: sqrt(0.5^2 - 0.2^2) as noise
    case AttitudeGrade::kGyrocompass:
      return {0.01, 0.01};  // iXblue Octans: roll/pitch accuracy 0.01 deg, resolution 0.01 deg
    case AttitudeGrade::kNone:
      break;
  }
  return {};
}

}  // namespace

const std::vector<std::string>& attitudeGradeNames() {
  static const std::vector<std::string> names{"fluxgate", "ahrs_mems", "gyrocompass"};
  return names;
}

void applyAttitudeGrade(AttitudeGrade grade, AttitudeConfig* config) {
  config->grade = grade;
  if (grade == AttitudeGrade::kNone) return;
  const AttitudeGradeTable t = table(grade);
  config->noise_deg = t.noise_deg;
  config->bias_sigma_deg = t.bias_sigma_deg;
}

}  // namespace deepnav::sim
