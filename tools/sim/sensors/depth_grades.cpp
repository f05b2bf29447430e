#include "tools/sim/sensors/depth_grades.h"

#include "tools/sim/sensors/depth_model.h"

namespace deepnav::sim {

namespace {

struct DepthGradeTable {
  double noise_m;
  double resolution_pa;
  double drift_m_per_h;
};

constexpr double kHoursPerYear = 365.25 * 24.0;
// Depth per pascal at the nominal density (1028 kg/m^3, g 9.80665): the datasheets give %FS of pressure.
constexpr double kMetresPerPascal = 1.0 / (1028.0 * 9.80665);

// tools/sim/README.md "Compass, attitude and depth errors" cites each figure.
DepthGradeTable table(DepthGrade grade) {
  switch (grade) {
    case DepthGrade::kStrainGauge: {
      constexpr double kFullScale_pa = 200e5;  // Keller 33X, 200 bar range (2000 m)
      // resolution 0.002 %FS; long-term stability 0.1 %FS per year; noise at the resolution.
      return {0.002e-2 * kFullScale_pa * kMetresPerPascal, 0.002e-2 * kFullScale_pa,
              0.1e-2 * kFullScale_pa * kMetresPerPascal / kHoursPerYear};
    }
    case DepthGrade::kQuartz: {
      constexpr double kFullScale_pa = 27.58e6;  // Digiquartz 4000 psia
      // resolution 1e-6 FS (0.0001 %); long-term stability 0.01 %FS per year; noise at the resolution.
      return {1e-6 * kFullScale_pa * kMetresPerPascal, 1e-6 * kFullScale_pa,
              0.01e-2 * kFullScale_pa * kMetresPerPascal / kHoursPerYear};
    }
    case DepthGrade::kNone:
      break;
  }
  return {};
}

}  // namespace

const std::vector<std::string>& depthGradeNames() {
  static const std::vector<std::string> names{"strain_gauge", "quartz"};
  return names;
}

void applyDepthGrade(DepthGrade grade, DepthConfig* config) {
  config->grade = grade;
  if (grade == DepthGrade::kNone) return;
  const DepthGradeTable t = table(grade);
  config->noise_m = t.noise_m;
  config->resolution_pa = t.resolution_pa;
  config->drift_m_per_h = t.drift_m_per_h;
}

}  // namespace deepnav::sim
