#pragma once
#include <string>
#include <vector>

namespace deepnav::sim {

struct CompassConfig;

// `compass.grade`: the heading instrument class. kNone (key absent) leaves every parameter as written.
//   fluxgate     a tilt-compensated fluxgate/magneto-inductive compass module (PNI TCM XB)
//   ahrs_mems    the magnetic heading of a MEMS AHRS (Xsens MTi-30)
//   gyrocompass  a FOG gyrocompass finding true north (iXblue Octans): not magnetic
// Figures and their sources: tools/sim/README.md, "Compass, attitude and depth errors".
enum class CompassGrade { kNone = 0, kFluxgate, kAhrsMems, kGyrocompass };

// Scenario names, in enum order from kFluxgate.
const std::vector<std::string>& compassGradeNames();
// Sets the parameters the grade covers (noise, residual bias sigma, true_north); the loader then reads
// the explicit keys over them.
void applyCompassGrade(CompassGrade grade, CompassConfig* config);

}  // namespace deepnav::sim
