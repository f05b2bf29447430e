#pragma once
#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include <Eigen/Core>

#include "nav/types/dvl_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"
#include "tools/sim/sensors/dvl_grades.h"
#include "tools/sim/sensors/dvl_ping_timing.h"

namespace deepnav::sim {

struct Scenario;
class DvlBeamCaster;
struct DvlEcho;

// Scenario key `dvl`: a 4-beam Janus bottom-tracking DVL looking down.
struct DvlConfig {
  bool enabled = true;
  double rate_hz = 5.0;
  std::array<double, 3> p_dvl_in_robot_m{-0.2, 0.0, -0.3};  // lever arm, robot frame (FLU)
  std::array<double, 3> mount_rpy_deg{0.0, 0.0, 0.0};       // R_robot_dvl, as the board knows it
  double noise_fraction_of_speed = 0.005;  // per-axis 1-sigma = fraction * |v| + floor
  double noise_floor_mps = 0.001;
  double min_altitude_m = 0.3;             // bottom lock only within [min, max] altitude
  double max_altitude_m = 50.0;
  double beam_angle_deg = 30.0;            // beam tilt from the DVL's -z axis
  double beam_azimuth_offset_deg = 45.0;   // azimuth of beam 0 from the DVL's +x; beams 90 deg apart
  double range_noise_m = 0.01;             // 1-sigma on each slant range

  // Sea-grade terms (tools/sim/README.md, "DVL grades"). All off by default; with all off the model is
  // the per-axis one above, bit for bit. Any one on switches to the beam model (usesBeamModel()).
  DvlGrade grade = DvlGrade::kNone;
  double beam_noise_fraction = 0.0;        // per-beam radial 1-sigma = fraction * |beam velocity| + floor
  double beam_noise_floor_mps = 0.0;
  double scale_factor_percent = 0.0;       // fixed scale error of velocities and ranges (sound speed)
  double scale_factor_sigma_percent = 0.0; // 1-sigma of a further scale error drawn per dive
  double bias_sigma_mps = 0.0;             // 1-sigma of a constant velocity bias per axis, drawn per dive
  std::array<double, 3> misalignment_rpy_deg{0.0, 0.0, 0.0};  // true mount = mount_rpy then this, unknown to the board
  bool ray_cast = false;                   // beams against the rendered scene, not a flat seabed
  double lock_range_jump_fraction = 0.0;   // a beam whose range changed by more than this fraction loses lock (0: off)
  double outlier_probability = 0.0;        // per locked beam and ping
  double outlier_magnitude_mps = 0.3;      // +- on that beam's radial velocity
  double max_ping_rate_hz = 0.0;           // 0: a ping per channel tick; else altitude-dependent, capped here
  double ping_processing_ms = 30.0;        // per ping, on top of the echo's travel time
  // Output latency: `timing.dvl.latency_ms` (sensor_timing.h), common to every sensor.

  bool usesBeamModel() const;
  bool operator==(const DvlConfig&) const = default;
};

// Bottom-track velocity of the DVL point (v + w x lever arm) in the DVL frame. Beam i points along
// (sin a cos az_i, sin a sin az_i, -cos a) in the DVL frame; its slant range is where it meets the
// seabed (flat at z = seabed_z_in_odom_m, or the scene with ray_cast). A beam locks when its range,
// converted to a vertical range with the nominal beam angle, is within [min_altitude_m, max_altitude_m];
// the velocity is valid with >= 3 locked beams (the dropout outside the altitude window).
// Per-axis model (no sea-grade term): white noise per axis on the true velocity. Beam model: each locked
// beam measures its radial velocity (scaled, noisy, sometimes an outlier), the velocity is their least-
// squares solution (dvl_beam_solver.h), then the per-dive bias and the per-axis noise are added.
class DvlModel {
 public:
  bool init(const DvlConfig& config, double seabed_z_in_odom_m, std::uint64_t seed, std::string* error);
  // For ray_cast: the beams meet the scene the renderer builds from (scenario, scene_seed).
  bool attachScene(const Scenario& scenario, std::uint64_t scene_seed, std::string* error);
  DvlSample measure(const KinematicState& truth, TimeUs t_us);
  // Whether the instrument pings at this channel tick (altitude-dependent ping rate; always true without
  // max_ping_rate_hz). measure() schedules the next ping.
  bool pingDue(TimeUs t_us) const { return ping_timing_.due(t_us); }

  // True velocity of the DVL point w.r.t. the seabed, in the instrument's true (misaligned) frame.
  Eigen::Vector3d trueVelocity_mps(const KinematicState& truth) const;
  // Per-axis 1-sigma of the per-axis velocity noise at a given speed.
  double sigmaAtSpeed_mps(double speed_mps) const;
  // Beam unit vector i in the DVL frame.
  Eigen::Vector3d beamInDvl(int i) const { return beams_in_dvl_[i]; }
  // This dive's draws: velocity and range scale (1 + error) and the velocity bias (DVL frame).
  double scale() const { return scale_; }
  const Eigen::Vector3d& bias_mps() const { return bias_mps_; }

 private:
  DvlSample measureBeams(const KinematicState& truth, TimeUs t_us, const std::array<double, 3>& velocity_noise,
                         const std::array<double, DvlSample::kBeams>& range_noise);
  bool echoOf(const Eigen::Vector3d& p_dvl_in_odom, const Eigen::Vector3d& d_in_odom, double t_s, DvlEcho* echo);

  DvlConfig config_;
  NormalRng rng_;
  NormalRng beam_rng_;  // beam model only: its own sub-stream, so the per-axis draws stay as they were
  bool beam_model_ = false;
  Eigen::Matrix3d R_robot_dvl_ = Eigen::Matrix3d::Identity();  // the instrument's true mounting
  Eigen::Vector3d p_dvl_in_robot_m_ = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, DvlSample::kBeams> beams_in_dvl_{};
  double seabed_z_in_odom_m_ = 0.0;
  double scale_ = 1.0;
  Eigen::Vector3d bias_mps_ = Eigen::Vector3d::Zero();
  std::array<double, DvlSample::kBeams> last_range_m_{};  // previous ping's ranges (NaN: no echo)
  DvlPingTiming ping_timing_;
  std::shared_ptr<DvlBeamCaster> caster_;  // ray_cast only; shared by copies of the model
};

}  // namespace deepnav::sim
