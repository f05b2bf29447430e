#pragma once
#include <string>
#include <vector>

namespace deepnav::sim {

struct AttitudeConfig;

// `attitude.grade`: the roll/pitch instrument class (the same instrument classes as `compass.grade`).
// kNone (key absent) leaves every parameter as written.
//   fluxgate     the accelerometer tilt of a compass module (PNI TCM XB)
//   ahrs_mems    a MEMS AHRS (Xsens MTi-30)
//   gyrocompass  a FOG gyrocompass / attitude unit (iXblue Octans)
// Figures and their sources: tools/sim/README.md, "Compass, attitude and depth errors".
enum class AttitudeGrade { kNone = 0, kFluxgate, kAhrsMems, kGyrocompass };

const std::vector<std::string>& attitudeGradeNames();  // in enum order from kFluxgate
void applyAttitudeGrade(AttitudeGrade grade, AttitudeConfig* config);

}  // namespace deepnav::sim
