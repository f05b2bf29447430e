#pragma once
#include <span>
#include <string>

#include "base/marker_observation.h"
#include "base/param_decl.h"

namespace deepnav {

// Uncertainty model of a pose from one square marker (per observation), with its defaults.
//
// Why this shape. A marker of side L at distance d appears s = f L / d pixels wide. With corner
// noise sigma_px, its scale (hence depth) is known to sigma_px / s relatively, so the depth error
// is
//   sigma_depth ~ sigma_px d^2 / (f L),                                                     (1)
// and its tilt to about sigma_px / s rad ~ sigma_px d / (f L). A camera-marker rotation error
// dtheta moves the camera's position seen from the marker by dtheta x d: again ~ d^2. Seen
// obliquely at angle a (from the normal), one side shrinks by cos(a), so both grow like 1 / cos(a).
// Hence, with k = 1 / cos(a) (a clamped to max_obliqueness_rad) and g = max(1, e_px /
// nominal_reprojection_px) (a pose that fits its corners badly is trusted less):
//   sigma_pos = pos_floor_m   + g k pos_per_d2_per_m  d^2      (metres, d in metres)          (2)
//   sigma_rot = rot_floor_rad + g k rot_per_d_rad_per_m d      (radians)                      (3)
// both multiplied by ambiguous_scale when the two IPPE solutions could not be told apart. The
// floors stand for calibration, marker placement and flatness. Defaults: f = 700 px, L = 0.15 m and
// sigma_px = 0.3 px give sigma_px / (f L) = 0.003 /m in (1); the defaults take about three times
// that for the unmodelled (refraction, blur, calibration drift), i.e. 3.3 cm and 1.25 deg at
// 1.5 m head-on. Each sigma is isotropic (the same on every axis), so the diagonal covariance it
// makes is the same in every frame: no rotation to the odom axes is needed.
struct MarkerCovarianceConfig {
  double pos_floor_m = 0.01;
  double pos_per_d2_per_m = 0.01;        // coefficient of d^2 in (2), 1/m
  double rot_floor_rad = 0.0087;         // 0.5 deg
  double rot_per_d_rad_per_m = 0.0087;   // coefficient of d in (3), rad/m (0.5 deg per m)
  double nominal_reprojection_px = 0.5;  // RMS corner error expected of a good detection, > 0
  double max_obliqueness_rad = 1.309;    // 75 deg: clamp of a in 1 / cos(a), [0, 1.5]
  double ambiguous_scale = 3.0;          // sigma factor for an ambiguous pose, >= 1
};

// The board keys of the model (section "markers" of a board file): unit, range and meaning of the fields a
// board sets, declared once; the defaults are the initialisers above.
std::span<const ParamDecl<MarkerCovarianceConfig>> markerCovarianceParams();

bool validateMarkerCovarianceConfig(const MarkerCovarianceConfig& config, std::string* error);

// 1-sigma of the camera-marker pose, eqs. (2) and (3).
struct MarkerPoseSigmas {
  double position_m = 0.0;
  double rotation_rad = 0.0;
};

MarkerPoseSigmas markerPoseSigmas(const MarkerObservation& obs,
                                  const MarkerCovarianceConfig& config);

}  // namespace deepnav
