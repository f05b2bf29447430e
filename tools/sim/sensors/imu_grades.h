#pragma once
#include <string>
#include <vector>

#include "tools/sim/sensors/imu_model.h"

namespace deepnav::sim {

// Scenario key `imu.grade`: the error terms of a class of IMU, from a public data sheet (sources and
// which figures are chosen rather than read: tools/sim/README.md, "Sensor grades: IMU").
//   mems       Xsens MTi-300 (MEMS AHRS)
//   tactical   Sensonor STIM300 (high-end MEMS IMU)
//   navigation Honeywell HG9900 (ring-laser-gyro navigation IMU)
enum class ImuGrade { kMems = 0, kTactical = 1, kNavigation = 2 };

// In the order of the enum, for YamlSection::choice.
const std::vector<std::string>& imuGradeNames();

// Sets every error term the grade covers (noise, biases, scale factor, misalignment); leaves rate,
// mounting, lever arm, vibration and `enabled` as they are. Explicit keys are read after this.
void applyImuGrade(ImuGrade grade, ImuConfig* config);

}  // namespace deepnav::sim
