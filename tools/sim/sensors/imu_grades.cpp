#include "tools/sim/sensors/imu_grades.h"

#include <cmath>

namespace deepnav::sim {

namespace {

constexpr double kStandardGravity_mps2 = 9.80665;
constexpr double kMicroG_mps2 = 1e-6 * kStandardGravity_mps2;
constexpr double kSqrtSPerSqrtH = 60.0;

// No data sheet gives a rate random walk K. Chosen: the +1/2 line K sqrt(tau / 3) meets the bias
// instability floor B at tau = 20 T_c, well after the Gauss-Markov peak (1.89 T_c), as in the Allan
// plots of the units: K = B sqrt(3 / (20 T_c)) [unit/sqrt(s)], returned per sqrt(h).
double rateRandomWalkPerSqrtH(double bias_instability, double correlation_time_s) {
  return bias_instability * std::sqrt(3.0 / (20.0 * correlation_time_s)) * kSqrtSPerSqrtH;
}

// A noise density in unit/sqrt(Hz) as a random walk in unit*s/sqrt(h).
double perSqrtHFromDensity(double density_per_sqrt_hz) { return density_per_sqrt_hz * kSqrtSPerSqrtH; }

struct GradeTable {
  double gyro_arw_deg_per_sqrt_h, gyro_bias_instability_deg_per_h, gyro_correlation_time_s;
  double gyro_turn_on_deg_per_h, gyro_scale_factor_ppm, gyro_misalignment_mrad;
  double accel_vrw_mps_per_sqrt_h, accel_bias_instability_mps2, accel_correlation_time_s;
  double accel_turn_on_mps2, accel_scale_factor_ppm, accel_misalignment_mrad;
};

// Figures marked (ds) are the data sheet's; the others are chosen (README, "Sensor grades: IMU").
GradeTable tableOf(ImuGrade grade) {
  switch (grade) {
    case ImuGrade::kMems:  // Xsens MTi-300 (Movella data sheet, May 2023)
      return {perSqrtHFromDensity(0.01),   // (ds) gyro noise density 0.01 deg/s/sqrt(Hz)
              10.0,                        // (ds) gyro in-run bias stability 10 deg/h
              100.0, 360.0, 1000.0, 1.0,   // chosen
              perSqrtHFromDensity(60.0 * kMicroG_mps2),  // (ds) accel noise density 60 ug/sqrt(Hz)
              15.0 * kMicroG_mps2,         // (ds) accel in-run bias stability 15 ug
              100.0, 2000.0 * kMicroG_mps2, 1000.0, 1.0};  // chosen
    case ImuGrade::kTactical:  // Sensonor STIM300, 10 g accelerometers (data sheet TS1524 rev. 9)
      return {0.15,                        // (ds) ARW 0.15 deg/sqrt(h)
              0.5,                         // (ds) bias instability 0.5 deg/h
              300.0,                       // chosen
              4.0,                         // (ds) bias repeatability 4 deg/h (1 sigma)
              500.0, 1.0,                  // (ds) scale factor accuracy 500 ppm, misalignment 1 mrad
              0.06,                        // (ds) VRW 0.06 m/s/sqrt(h)
              50.0 * kMicroG_mps2,         // (ds) bias instability 0.05 mg
              300.0,                       // chosen
              750.0 * kMicroG_mps2,        // (ds) bias run-run 0.75 mg
              300.0, 1.0};                 // (ds) scale factor accuracy 300 ppm, misalignment 1 mrad
    case ImuGrade::kNavigation:  // Honeywell HG9900 (brochure N61-1638-000-000)
      return {0.002,                       // (ds) ARW 0.002 deg/sqrt(h)
              0.0035,                      // (ds) gyro bias 0.0035 deg/h
              3600.0,                      // chosen
              0.0035,                      // (ds) the same bias figure as the turn-on bias
              5.0,                         // (ds) gyro scale factor 5 ppm
              0.05,                        // chosen
              0.0012,                      // chosen (the brochure gives no VRW)
              25.0 * kMicroG_mps2,         // (ds) accel bias 25 ug
              3600.0,                      // chosen
              25.0 * kMicroG_mps2,         // (ds) the same bias figure as the turn-on bias
              100.0,                       // (ds) accel scale factor 100 ppm
              0.05};                       // chosen
  }
  return tableOf(ImuGrade::kTactical);
}

}  // namespace

const std::vector<std::string>& imuGradeNames() {
  static const std::vector<std::string> names{"mems", "tactical", "navigation"};
  return names;
}

void applyImuGrade(ImuGrade grade, ImuConfig* c) {
  const GradeTable t = tableOf(grade);
  c->gyro_noise_deg_per_sqrt_h = t.gyro_arw_deg_per_sqrt_h;
  c->gyro_bias_instability_deg_per_h = t.gyro_bias_instability_deg_per_h;
  c->gyro_bias_correlation_time_s = t.gyro_correlation_time_s;
  c->gyro_bias_rw_deg_per_h_per_sqrt_h = rateRandomWalkPerSqrtH(t.gyro_bias_instability_deg_per_h, t.gyro_correlation_time_s);
  c->gyro_initial_bias_deg_per_h = t.gyro_turn_on_deg_per_h;
  c->gyro_scale_factor_ppm = t.gyro_scale_factor_ppm;
  c->gyro_misalignment_mrad = t.gyro_misalignment_mrad;
  c->accel_noise_mps_per_sqrt_h = t.accel_vrw_mps_per_sqrt_h;
  c->accel_bias_instability_mps2 = t.accel_bias_instability_mps2;
  c->accel_bias_correlation_time_s = t.accel_correlation_time_s;
  c->accel_bias_rw_mps2_per_sqrt_h = rateRandomWalkPerSqrtH(t.accel_bias_instability_mps2, t.accel_correlation_time_s);
  c->accel_initial_bias_mps2 = t.accel_turn_on_mps2;
  c->accel_scale_factor_ppm = t.accel_scale_factor_ppm;
  c->accel_misalignment_mrad = t.accel_misalignment_mrad;
}

}  // namespace deepnav::sim
