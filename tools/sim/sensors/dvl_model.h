#pragma once
#include <array>
#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "nav/types/dvl_sample.h"
#include "tools/sim/kinematic_state.h"
#include "tools/sim/normal_rng.h"

namespace deepnav::sim {

// Scenario key `dvl`: a 4-beam Janus bottom-tracking DVL looking down.
struct DvlConfig {
  bool enabled = true;
  double rate_hz = 5.0;
  std::array<double, 3> p_dvl_in_robot_m{-0.2, 0.0, -0.3};  // lever arm, robot frame (FLU)
  std::array<double, 3> mount_rpy_deg{0.0, 0.0, 0.0};       // R_robot_dvl
  double noise_fraction_of_speed = 0.005;  // per-axis 1-sigma = fraction * |v| + floor
  double noise_floor_mps = 0.001;
  double min_altitude_m = 0.3;             // bottom lock only within [min, max] altitude
  double max_altitude_m = 50.0;
  double beam_angle_deg = 30.0;            // beam tilt from the DVL's -z axis
  double beam_azimuth_offset_deg = 45.0;   // azimuth of beam 0 from the DVL's +x; beams 90 deg apart
  double range_noise_m = 0.01;             // 1-sigma on each slant range

  bool operator==(const DvlConfig&) const = default;
};

// Bottom-track velocity of the DVL point (v + w x lever arm) in the DVL frame, over a flat seabed at
// z = seabed_z_in_odom_m. Beam i points along (sin a cos az_i, sin a sin az_i, -cos a) in the DVL frame;
// its slant range is where it meets the seabed. A beam locks when its range, converted to a vertical
// range with the nominal beam angle, is within [min_altitude_m, max_altitude_m]; the velocity is valid
// with >= 3 locked beams (the dropout outside the altitude window). Noise is white, per axis.
class DvlModel {
 public:
  bool init(const DvlConfig& config, double seabed_z_in_odom_m, std::uint64_t seed, std::string* error);
  DvlSample measure(const KinematicState& truth, TimeUs t_us);

  // True velocity of the DVL point w.r.t. the seabed, DVL frame.
  Eigen::Vector3d trueVelocity_mps(const KinematicState& truth) const;
  // Per-axis 1-sigma of the velocity noise at a given speed.
  double sigmaAtSpeed_mps(double speed_mps) const;
  // Beam unit vector i in the DVL frame.
  Eigen::Vector3d beamInDvl(int i) const { return beams_in_dvl_[i]; }

 private:
  DvlConfig config_;
  NormalRng rng_;
  Eigen::Matrix3d R_robot_dvl_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p_dvl_in_robot_m_ = Eigen::Vector3d::Zero();
  std::array<Eigen::Vector3d, DvlSample::kBeams> beams_in_dvl_{};
  double seabed_z_in_odom_m_ = 0.0;
};

}  // namespace deepnav::sim
