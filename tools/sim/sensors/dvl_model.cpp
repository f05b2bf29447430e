#include "tools/sim/sensors/dvl_model.h"

#include <cmath>

#include "tools/sim/rotation.h"

namespace deepnav::sim {

bool DvlModel::init(const DvlConfig& config, double seabed_z_in_odom_m, std::uint64_t seed,
                    std::string* error) {
  if (!(config.rate_hz > 0.0) || !(config.min_altitude_m < config.max_altitude_m)) {
    if (error) *error = "dvl: rate_hz must be > 0 and min_altitude_m < max_altitude_m";
    return false;
  }
  config_ = config;
  seabed_z_in_odom_m_ = seabed_z_in_odom_m;
  rng_ = NormalRng(seed);
  R_robot_dvl_ = rotationFromRpyDeg(config.mount_rpy_deg);
  p_dvl_in_robot_m_ = toVector(config.p_dvl_in_robot_m);
  const double tilt = config.beam_angle_deg * kDegToRad;
  for (int i = 0; i < DvlSample::kBeams; ++i) {
    const double azimuth = (config.beam_azimuth_offset_deg + 90.0 * i) * kDegToRad;
    beams_in_dvl_[i] = {std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), -std::cos(tilt)};
  }
  return true;
}

double DvlModel::sigmaAtSpeed_mps(double speed_mps) const {
  return config_.noise_fraction_of_speed * speed_mps + config_.noise_floor_mps;
}

Eigen::Vector3d DvlModel::trueVelocity_mps(const KinematicState& truth) const {
  const Eigen::Vector3d v_in_robot =
      truth.q_odom_robot.conjugate() * truth.v_robot_in_odom_mps + truth.w_robot_radps.cross(p_dvl_in_robot_m_);
  return R_robot_dvl_.transpose() * v_in_robot;
}

DvlSample DvlModel::measure(const KinematicState& truth, TimeUs t_us) {
  DvlSample s;
  s.t_us = t_us;
  // Draw every random number whatever the outcome, so a dropout does not shift later noise.
  std::array<double, 3> velocity_noise{};
  for (double& n : velocity_noise) n = rng_.normal();
  std::array<double, DvlSample::kBeams> range_noise{};
  for (double& n : range_noise) n = rng_.normal(config_.range_noise_m);

  const Eigen::Matrix3d R_odom_dvl = truth.q_odom_robot.toRotationMatrix() * R_robot_dvl_;
  const Eigen::Vector3d p_dvl_in_odom = truth.p_robot_in_odom_m + truth.q_odom_robot * p_dvl_in_robot_m_;
  const double height_m = p_dvl_in_odom.z() - seabed_z_in_odom_m_;
  const double cos_tilt = std::cos(config_.beam_angle_deg * kDegToRad);
  int locked = 0;
  double altitude_sum_m = 0.0;
  for (int i = 0; i < DvlSample::kBeams; ++i) {
    const double down = -(R_odom_dvl * beams_in_dvl_[i]).z();
    if (height_m <= 0.0 || down <= 1e-6) continue;
    const double range_m = height_m / down + range_noise[i];
    const double vertical_m = range_m * cos_tilt;  // what the instrument reports, without tilt correction
    if (vertical_m < config_.min_altitude_m || vertical_m > config_.max_altitude_m) continue;
    s.beam_range_m[i] = range_m;
    s.beam_valid_mask |= static_cast<std::uint8_t>(1u << i);
    altitude_sum_m += vertical_m;
    ++locked;
  }
  if (locked > 0) s.altitude_m = altitude_sum_m / locked;
  s.valid = locked >= 3;
  if (!s.valid) return s;

  const Eigen::Vector3d v_true = trueVelocity_mps(truth);
  const double sigma = sigmaAtSpeed_mps(v_true.norm());
  s.v_dvl_mps = v_true + sigma * Eigen::Vector3d(velocity_noise[0], velocity_noise[1], velocity_noise[2]);
  s.fom_mps = sigma;
  s.cov_v_dvl_mps2 = Eigen::Matrix3d::Identity() * sigma * sigma;
  return s;
}

}  // namespace deepnav::sim
