#pragma once
#include <array>

#include <Eigen/Core>

#include "tools/sim/panel_geometry.h"

namespace deepnav::sim {

// The steel panel's magnetic signature as one point dipole in the panel frame P (panel_geometry.h):
// a permanent moment (remanent magnetisation, fixed in P) plus a moment induced by the Earth's field,
// m_induced = k * B_earth (k in A m^2 per uT). For a highly permeable body, k is that of the equivalent
// sphere of radius a: m = 4 pi a^3 H0 = (4 pi a^3 / mu0) B0, i.e. k = 10 a^3 A m^2/uT (a in m)
// (magnetised sphere in a uniform field, Jackson, Classical Electrodynamics 3rd ed., sec. 5.11, mu -> inf).
struct PanelMagnetConfig {
  std::array<double, 3> permanent_moment_am2{0.0, 0.0, 0.0};  // in P
  double induced_moment_am2_per_ut = 0.0;                     // along the Earth's total field
  std::array<double, 3> dipole_position_m{0.0, 0.0, 0.75};    // in P (default: mid-height of the panel)

  bool active() const {
    return permanent_moment_am2 != std::array<double, 3>{0.0, 0.0, 0.0} || induced_moment_am2_per_ut != 0.0;
  }
  bool operator==(const PanelMagnetConfig&) const = default;
};

// The Earth's main field at the site, in the odometry frame O (ENU): horizontal component towards
// magnetic north (true heading = declination), vertical component positive down (northern hemisphere).
struct EarthField {
  double horizontal_ut = 20.0;
  double vertical_down_ut = 40.0;
  double declination_rad = 0.0;

  Eigen::Vector3d inOdom_ut() const;
};

// The dipole field of the panel, B(r) = mu0/(4 pi) (3 (m.u) u - m) / |r|^3, in uT, in O.
class PanelMagneticField {
 public:
  void init(const PanelMagnetConfig& config, const PanelGeometry& panel, double seabed_z_in_odom_m,
            const EarthField& earth);
  Eigen::Vector3d field_ut(const Eigen::Vector3d& p_in_odom_m) const;

 private:
  Eigen::Vector3d p_dipole_in_odom_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d m_in_odom_am2_ = Eigen::Vector3d::Zero();
};

// Heading error of a magnetic compass from a disturbance field: the compass aligns with the horizontal
// part of earth + disturbance instead of the Earth's, so with h(v) = atan2(v_east, v_north) its reading
// is true heading - h(earth + disturbance) instead of true heading - h(earth). Returned as the error added
// to the reading, h(earth) - h(earth + disturbance), wrapped to [-pi, pi): exact, no small-field expansion.
double disturbanceHeadingError_rad(const Eigen::Vector3d& earth_ut, const Eigen::Vector3d& disturbance_ut);

}  // namespace deepnav::sim
