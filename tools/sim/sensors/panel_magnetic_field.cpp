#include "tools/sim/sensors/panel_magnetic_field.h"

#include <cmath>

#include <Eigen/Geometry>

#include "tools/sim/rotation.h"

namespace deepnav::sim {

namespace {
constexpr double kMu0Over4Pi_TmPerA = 1e-7;
constexpr double kTeslaToMicroTesla = 1e6;
}  // namespace

Eigen::Vector3d EarthField::inOdom_ut() const {
  // Magnetic north lies at true heading D: (east, north) = (sin D, cos D); z is up in O.
  return {horizontal_ut * std::sin(declination_rad), horizontal_ut * std::cos(declination_rad), -vertical_down_ut};
}

void PanelMagneticField::init(const PanelMagnetConfig& config, const PanelGeometry& panel,
                              double seabed_z_in_odom_m, const EarthField& earth) {
  const Eigen::Matrix3d R_odom_panel =
      Eigen::AngleAxisd(panel.front_yaw_deg * kDegToRad, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d p_panel_in_odom_m(panel.centre_in_odom_m[0], panel.centre_in_odom_m[1], seabed_z_in_odom_m);
  p_dipole_in_odom_m_ = p_panel_in_odom_m + R_odom_panel * toVector(config.dipole_position_m);
  m_in_odom_am2_ = R_odom_panel * toVector(config.permanent_moment_am2) +
                   config.induced_moment_am2_per_ut * earth.inOdom_ut();
}

Eigen::Vector3d PanelMagneticField::field_ut(const Eigen::Vector3d& p_in_odom_m) const {
  const Eigen::Vector3d r = p_in_odom_m - p_dipole_in_odom_m_;
  const double r_m = r.norm();
  if (!(r_m > 0.0)) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d u = r / r_m;
  const double scale = kMu0Over4Pi_TmPerA * kTeslaToMicroTesla / (r_m * r_m * r_m);
  return scale * (3.0 * m_in_odom_am2_.dot(u) * u - m_in_odom_am2_);
}

double disturbanceHeadingError_rad(const Eigen::Vector3d& earth_ut, const Eigen::Vector3d& disturbance_ut) {
  const double ex = earth_ut.x(), ey = earth_ut.y();
  const double tx = ex + disturbance_ut.x(), ty = ey + disturbance_ut.y();
  // h(e) - h(t) with h(v) = atan2(v_x, v_y) is the counter-clockwise angle from e to t in the EN plane.
  return std::atan2(ex * ty - ey * tx, ex * tx + ey * ty);
}

}  // namespace deepnav::sim
