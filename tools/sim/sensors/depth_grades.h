#pragma once
#include <string>
#include <vector>

namespace deepnav::sim {

struct DepthConfig;

// `depth.grade`: the pressure sensor class. kNone (key absent) leaves every parameter as written.
//   strain_gauge  a piezoresistive / strain-gauge transmitter (Keller Series 33X, 200 bar)
//   quartz        a resonant quartz sensor (Paroscientific Digiquartz, 4000 psia = 27.6 MPa)
// Figures and their sources: tools/sim/README.md, "Compass, attitude and depth errors".
enum class DepthGrade { kNone = 0, kStrainGauge, kQuartz };

const std::vector<std::string>& depthGradeNames();  // in enum order from kStrainGauge
void applyDepthGrade(DepthGrade grade, DepthConfig* config);

}  // namespace deepnav::sim
