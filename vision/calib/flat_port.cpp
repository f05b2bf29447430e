#include "vision/calib/flat_port.h"

#include <array>
#include <cmath>

namespace deepnav {
namespace {

using D = ParamDecl<FlatPort>;

const std::array kFlatPortParams = {
    D{"pinhole_to_glass_m", ParamType::kDouble, "m", 0, 0.5, "",
      "flat port: distance from the pinhole (entrance pupil) to the inner glass surface, d0",
      DEEPNAV_PARAM_FIELD(FlatPort, pinhole_to_glass_m)},
    D{"glass_thickness_m", ParamType::kDouble, "m", 0, 0.2, "", "flat port: glass thickness, d1",
      DEEPNAV_PARAM_FIELD(FlatPort, glass_thickness_m)},
    D{"n_air", ParamType::kDouble, "-", 1, 2, "", "flat port: refractive index inside the housing",
      DEEPNAV_PARAM_FIELD(FlatPort, n_air)},
    D{"n_glass", ParamType::kDouble, "-", 1, 3, "",
      "flat port: refractive index of the glass (acrylic 1.49, BK7 1.52, sapphire 1.77)",
      DEEPNAV_PARAM_FIELD(FlatPort, n_glass)},
    D{"n_water", ParamType::kDouble, "-", 1, 2, "", "flat port: refractive index of the water",
      DEEPNAV_PARAM_FIELD(FlatPort, n_water)},
};

// tan of the angle whose sine is s (|s| < 1).
double tanFromSin(double s) { return s / std::sqrt(1.0 - s * s); }

// Derivative of tanFromSin with respect to s.
double dTanFromSin(double s) {
  const double c2 = 1.0 - s * s;
  return 1.0 / (c2 * std::sqrt(c2));
}

}  // namespace

std::span<const ParamDecl<FlatPort>> flatPortParams() { return kFlatPortParams; }

bool validateFlatPort(const FlatPort& p, std::string* error) {
  if (!checkParamRanges(flatPortParams(), p, "FlatPort", kCameraPortSection, error)) return false;
  if (!(p.n_water > p.n_air)) {
    if (error) *error = "n_water must be above n_air";
    return false;
  }
  return true;
}

bool refractDirection(const Eigen::Vector3d& incident, const Eigen::Vector3d& normal, double n_from,
                      double n_to, Eigen::Vector3d* refracted) {
  // Orient the normal against the incident ray: cos_i = -n.i > 0.
  Eigen::Vector3d n = normal;
  double cos_i = -n.dot(incident);
  if (cos_i < 0.0) {
    n = -n;
    cos_i = -cos_i;
  }
  const double eta = n_from / n_to;
  const double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t > 1.0) return false;  // total internal reflection
  // t = eta i + (eta cos_i - cos_t) n (e.g. Glassner, An Introduction to Ray Tracing, ch. 6).
  *refracted = eta * incident + (eta * cos_i - std::sqrt(1.0 - sin2_t)) * n;
  return true;
}

bool traceThroughPort(const FlatPort& port, const Eigen::Vector3d& dir_cam, PortRay* ray) {
  if (!(dir_cam.z() > 0.0)) return false;
  const Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d d_air = dir_cam.normalized();
  const Eigen::Vector3d p_inner = d_air * (port.pinhole_to_glass_m / d_air.z());
  Eigen::Vector3d d_glass;
  if (!refractDirection(d_air, normal, port.n_air, port.n_glass, &d_glass)) return false;
  const Eigen::Vector3d p_outer = p_inner + d_glass * (port.glass_thickness_m / d_glass.z());
  Eigen::Vector3d d_water;
  if (!refractDirection(d_glass, normal, port.n_glass, port.n_water, &d_water)) return false;
  ray->origin_m = p_outer;
  ray->dir = d_water.normalized();
  return true;
}

bool projectThroughPort(const FlatPort& port, const Eigen::Vector3d& p_cam_m, Eigen::Vector2d* xy_norm) {
  const double d0 = port.pinhole_to_glass_m;
  const double d1 = port.glass_thickness_m;
  const double z_water = p_cam_m.z() - d0 - d1;  // path length along the axis in water
  if (!(z_water > 0.0)) return false;
  const double r = std::hypot(p_cam_m.x(), p_cam_m.y());
  if (r == 0.0) {
    *xy_norm = Eigen::Vector2d::Zero();
    return true;
  }
  // Unknown: s = sin(theta_air). Snell: n_a s = n_g s_g = n_w s_w. The radial offset reached at depth z
  // grows monotonically with s, so the root is bracketed in [0, s_max) and Newton is safeguarded by
  // bisection.
  const double kg = port.n_air / port.n_glass;
  const double kw = port.n_air / port.n_water;
  const double s_max = std::min(1.0, std::min(1.0 / kg, 1.0 / kw)) * (1.0 - 1e-12);
  auto residual = [&](double s) {
    return d0 * tanFromSin(s) + d1 * tanFromSin(kg * s) + z_water * tanFromSin(kw * s) - r;
  };
  auto slope = [&](double s) {
    return d0 * dTanFromSin(s) + d1 * kg * dTanFromSin(kg * s) + z_water * kw * dTanFromSin(kw * s);
  };
  double lo = 0.0;
  double hi = s_max;
  if (residual(hi) < 0.0) return false;  // beyond the widest ray
  double s = std::min(0.5 * hi, r / std::hypot(r, z_water) / kw);
  for (int it = 0; it < 100; ++it) {
    const double f = residual(s);
    if (f > 0.0) hi = s; else lo = s;
    double next = s - f / slope(s);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - s) < 1e-15) {
      s = next;
      break;
    }
    s = next;
  }
  const double t = tanFromSin(s);
  *xy_norm = Eigen::Vector2d(p_cam_m.x(), p_cam_m.y()) * (t / r);
  return true;
}

double axisCrossingZ(const FlatPort& port, double theta_air_rad) {
  if (theta_air_rad == 0.0) return paraxialAxisCrossingZ(port);
  const double s = std::sin(theta_air_rad);
  const double d0 = port.pinhole_to_glass_m;
  const double d1 = port.glass_thickness_m;
  const double r_out = d0 * tanFromSin(s) + d1 * tanFromSin(s * port.n_air / port.n_glass);
  return d0 + d1 - r_out / tanFromSin(s * port.n_air / port.n_water);
}

double paraxialAxisCrossingZ(const FlatPort& port) {
  return port.pinhole_to_glass_m * (1.0 - port.n_water / port.n_air) +
         port.glass_thickness_m * (1.0 - port.n_water / port.n_glass);
}

double optimalPinholeToGlassM(const FlatPort& port) {
  const double n = port.n_water / port.n_air;
  const double m = port.n_water / port.n_glass;
  return port.glass_thickness_m * m * (1.0 - m * m) / (n * (n * n - 1.0));
}

}  // namespace deepnav
