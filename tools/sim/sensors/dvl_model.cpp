#include "tools/sim/sensors/dvl_model.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tools/sim/rotation.h"
#include "tools/sim/sensors/dvl_beam_caster.h"
#include "tools/sim/sensors/dvl_beam_solver.h"

namespace deepnav::sim {

namespace {

// Sub-streams of the model's seed for the beam model (new draws only; the per-axis model keeps the seed).
constexpr std::uint64_t kBeamStream = 1000;  // per ping: beam noise and outliers
constexpr std::uint64_t kDiveStream = 1001;  // per dive: scale factor and bias

double randomSign(double uniform) { return uniform <= 0.5 ? -1.0 : 1.0; }

}  // namespace

bool DvlConfig::usesBeamModel() const {
  return beam_noise_fraction > 0.0 || beam_noise_floor_mps > 0.0 || scale_factor_percent != 0.0 ||
         scale_factor_sigma_percent > 0.0 || bias_sigma_mps > 0.0 ||
         misalignment_rpy_deg != std::array<double, 3>{0.0, 0.0, 0.0} || ray_cast || lock_range_jump_fraction > 0.0 ||
         outlier_probability > 0.0 || max_ping_rate_hz > 0.0;
}

bool DvlModel::init(const DvlConfig& config, double seabed_z_in_odom_m, std::uint64_t seed, std::string* error) {
  if (!(config.rate_hz > 0.0) || !(config.min_altitude_m < config.max_altitude_m)) {
    if (error) *error = "dvl: rate_hz must be > 0 and min_altitude_m < max_altitude_m";
    return false;
  }
  config_ = config;
  seabed_z_in_odom_m_ = seabed_z_in_odom_m;
  rng_ = NormalRng(seed);
  p_dvl_in_robot_m_ = toVector(config.p_dvl_in_robot_m);
  const double tilt = config.beam_angle_deg * kDegToRad;
  for (int i = 0; i < DvlSample::kBeams; ++i) {
    const double azimuth = (config.beam_azimuth_offset_deg + 90.0 * i) * kDegToRad;
    beams_in_dvl_[i] = {std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), -std::cos(tilt)};
  }
  beam_model_ = config.usesBeamModel();
  caster_.reset();
  if (!beam_model_) {
    R_robot_dvl_ = rotationFromRpyDeg(config.mount_rpy_deg);
    return true;
  }
  R_robot_dvl_ = rotationFromRpyDeg(config.mount_rpy_deg) * rotationFromRpyDeg(config.misalignment_rpy_deg);
  beam_rng_ = NormalRng(NormalRng::subSeed(seed, kBeamStream));
  NormalRng dive(NormalRng::subSeed(seed, kDiveStream));
  scale_ = 1.0 + (config.scale_factor_percent + dive.normal(config.scale_factor_sigma_percent)) / 100.0;
  for (int i = 0; i < 3; ++i) bias_mps_[i] = dive.normal(config.bias_sigma_mps);
  last_range_m_.fill(std::numeric_limits<double>::quiet_NaN());
  ping_timing_.init(config.max_ping_rate_hz, config.ping_processing_ms * 1e-3);
  return true;
}

bool DvlModel::attachScene(const Scenario& scenario, std::uint64_t scene_seed, std::string* error) {
  auto caster = std::make_shared<DvlBeamCaster>();
  if (!caster->init(scenario, scene_seed, error)) return false;
  caster_ = std::move(caster);
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
  if (beam_model_) return measureBeams(truth, t_us, velocity_noise, range_noise);

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

bool DvlModel::echoOf(const Eigen::Vector3d& p_dvl_in_odom, const Eigen::Vector3d& d_in_odom, double t_s,
                      DvlEcho* echo) {
  if (caster_) {
    // Farther than this the vertical range is outside the window whatever the scale error.
    const double max_range_m = 1.5 * config_.max_altitude_m / std::cos(config_.beam_angle_deg * kDegToRad) + 1.0;
    return caster_->cast(p_dvl_in_odom, d_in_odom, t_s, max_range_m, echo);
  }
  const double height_m = p_dvl_in_odom.z() - seabed_z_in_odom_m_;
  const double down = -d_in_odom.z();
  if (height_m <= 0.0 || down <= 1e-6) return false;
  echo->range_m = height_m / down;
  echo->v_target_in_odom_mps.setZero();
  return true;
}

DvlSample DvlModel::measureBeams(const KinematicState& truth, TimeUs t_us, const std::array<double, 3>& velocity_noise,
                                 const std::array<double, DvlSample::kBeams>& range_noise) {
  std::array<double, DvlSample::kBeams> beam_noise{}, outlier_draw{}, outlier_sign{};
  for (int i = 0; i < DvlSample::kBeams; ++i) {
    beam_noise[i] = beam_rng_.normal();
    outlier_draw[i] = beam_rng_.uniform();
    outlier_sign[i] = beam_rng_.uniform();
  }
  DvlSample s;
  s.t_us = t_us;
  const Eigen::Matrix3d R_odom_dvl = truth.q_odom_robot.toRotationMatrix() * R_robot_dvl_;
  const Eigen::Vector3d p_dvl_in_odom = truth.p_robot_in_odom_m + truth.q_odom_robot * p_dvl_in_robot_m_;
  const Eigen::Vector3d v_dvl = trueVelocity_mps(truth);
  const double cos_tilt = std::cos(config_.beam_angle_deg * kDegToRad);
  const double ping_t_s = usToS(t_us);
  std::array<double, DvlSample::kBeams> u_mps{}, sigma_mps{};
  int locked = 0;
  double altitude_sum_m = 0.0, longest_m = 0.0;
  for (int i = 0; i < DvlSample::kBeams; ++i) {
    DvlEcho echo;
    if (!echoOf(p_dvl_in_odom, R_odom_dvl * beams_in_dvl_[i], ping_t_s, &echo)) {
      last_range_m_[i] = std::numeric_limits<double>::quiet_NaN();
      continue;
    }
    // A sound-speed error scales the travel-time ranges and the Doppler velocities alike.
    const double range_m = echo.range_m * scale_ + range_noise[i];
    const double previous_m = last_range_m_[i];
    last_range_m_[i] = range_m;
    const double vertical_m = range_m * cos_tilt;
    if (vertical_m < config_.min_altitude_m || vertical_m > config_.max_altitude_m) continue;
    // The bottom tracker expects the echo near the last one: a jump (a beam sliding onto the panel, a
    // fish crossing) costs the lock for this ping; from the next ping on it tracks the new surface.
    if (config_.lock_range_jump_fraction > 0.0 && std::isfinite(previous_m) &&
        std::abs(range_m - previous_m) > config_.lock_range_jump_fraction * previous_m)
      continue;
    const Eigen::Vector3d v_rel = v_dvl - R_odom_dvl.transpose() * echo.v_target_in_odom_mps;
    sigma_mps[i] = config_.beam_noise_fraction * std::abs(beams_in_dvl_[i].dot(v_rel)) + config_.beam_noise_floor_mps;
    u_mps[i] = scale_ * beams_in_dvl_[i].dot(v_rel) + sigma_mps[i] * beam_noise[i];
    if (outlier_draw[i] < config_.outlier_probability)
      u_mps[i] += randomSign(outlier_sign[i]) * config_.outlier_magnitude_mps;
    s.beam_range_m[i] = range_m;
    s.beam_valid_mask |= static_cast<std::uint8_t>(1u << i);
    altitude_sum_m += vertical_m;
    longest_m = std::max(longest_m, range_m);
    ++locked;
  }
  // Without a lock the instrument listens over its whole window before the next ping.
  ping_timing_.pinged(t_us, locked > 0 ? longest_m : config_.max_altitude_m / cos_tilt);
  if (locked > 0) s.altitude_m = altitude_sum_m / locked;
  Eigen::Vector3d v_mps;
  Eigen::Matrix3d cov_mps2;
  s.valid = solveDvlBeams(beams_in_dvl_, u_mps, sigma_mps, s.beam_valid_mask, &v_mps, &cov_mps2);
  if (!s.valid) return s;
  const double sigma_axis = sigmaAtSpeed_mps(v_dvl.norm());
  s.v_dvl_mps = v_mps + bias_mps_ +
                sigma_axis * Eigen::Vector3d(velocity_noise[0], velocity_noise[1], velocity_noise[2]);
  s.cov_v_dvl_mps2 = cov_mps2 + Eigen::Matrix3d::Identity() * sigma_axis * sigma_axis;
  s.fom_mps = std::sqrt(s.cov_v_dvl_mps2.trace() / 3.0);
  return s;
}

}  // namespace deepnav::sim
