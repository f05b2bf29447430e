#pragma once
#include <span>
#include <string>

#include <Eigen/Core>

#include "base/param_decl.h"

namespace deepnav {

// A flat port in front of a pinhole camera, glass parallel to the image plane (the axial-camera case of
// Łuczyński, Pfingsthorn and Birk, Ocean Engineering 2017). Camera optical frame: z along the optical
// axis; the inner glass surface is the plane z = pinhole_to_glass_m, the outer one z = pinhole_to_glass_m
// + glass_thickness_m. Air (n_air) between pinhole and glass, water (n_water) outside.
struct FlatPort {
  double pinhole_to_glass_m = 0.0;  // d0
  double glass_thickness_m = 0.0;   // d1
  double n_air = 1.0;
  double n_glass = 1.49;            // acrylic; BK7 glass 1.52, sapphire 1.77
  double n_water = 1.34;            // sea water, visible light

  bool operator==(const FlatPort&) const = default;
};

// The board keys of the port (section kCameraPortSection of a board file): unit, range and meaning,
// declared once; the defaults are the initialisers above.
inline constexpr const char* kCameraPortSection = "camera.port";
std::span<const ParamDecl<FlatPort>> flatPortParams();

// False with a message naming the field when a parameter is outside its declared range or the water is
// not denser than the air.
bool validateFlatPort(const FlatPort& port, std::string* error);

// Vector form of Snell's law: refracts the unit direction `incident` at a surface of unit normal
// `normal` (either orientation), going from index n_from to n_to. False on total internal reflection.
bool refractDirection(const Eigen::Vector3d& incident, const Eigen::Vector3d& normal, double n_from,
                      double n_to, Eigen::Vector3d* refracted);

// A ray in water after the port: it leaves the outer glass surface at origin_m, along the unit dir.
struct PortRay {
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d dir = Eigen::Vector3d::UnitZ();
};

// Traces the camera ray of direction dir_cam (z > 0, any length) from the pinhole through both glass
// surfaces. False when the ray does not reach the glass or is totally reflected.
bool traceThroughPort(const FlatPort& port, const Eigen::Vector3d& dir_cam, PortRay* ray);

// Exact refractive projection: the normalised image coordinates (x, y) = tan(theta_air) * radial unit
// of the camera ray that reaches the point p_cam_m (in water, z beyond the outer surface). Solves the
// radial equation d0 tan(ta) + d1 tan(tg) + (z - d0 - d1) tan(tw) = r by safeguarded Newton.
bool projectThroughPort(const FlatPort& port, const Eigen::Vector3d& p_cam_m, Eigen::Vector2d* xy_norm);

// Where the water ray of an air ray at angle theta_air (rad) from the axis, extended backwards, crosses
// the optical axis (z in the camera frame). A pinhole would give one z for every angle; a flat port
// spreads it (the axial camera), which is what the PinAx virtual pinhole approximates.
double axisCrossingZ(const FlatPort& port, double theta_air_rad);

// Paraxial limit of axisCrossingZ: d0 (1 - n_w/n_a) + d1 (1 - n_w/n_g).
double paraxialAxisCrossingZ(const FlatPort& port);

// The pinhole-to-glass distance d0 for which the axis crossings of a glass of the port's thickness agree
// to second order in the angle (air and glass terms cancel): d0* = d1 m (1 - m^2) / (n (n^2 - 1)),
// n = n_w / n_a, m = n_w / n_g. Building the housing with d0 near d0* makes the port nearly a pinhole.
double optimalPinholeToGlassM(const FlatPort& port);

}  // namespace deepnav
