#pragma once
#include <span>
#include <string>

#include <opencv2/core.hpp>
#include <Eigen/Core>

#include "vision/calib/flat_port.h"

namespace deepnav {

// The PinAx model (Łuczyński, Pfingsthorn and Birk, "The Pinax-model for accurate and efficient
// refraction correction of underwater cameras in flat-pane housings", Ocean Engineering 2017): a camera
// behind a flat port is an axial camera (its water rays cross the optical axis at slightly different
// points); PinAx replaces it by a virtual pinhole on the axis, and maps each virtual pixel onto the real
// image through the exact refraction of the point it sees at a reference distance. The mapping is
// exact at that distance and, for d0 near optimalPinholeToGlassM, within a tenth of a pixel over the
// working range (tests/unit/calib_pinax_test.cpp).
struct PinaxConfig {
  FlatPort port;
  double reference_distance_m = 2.0;  // along the axis from the real pinhole, in water
};

// The board key of the mapping (section kCameraPortSection, beside the port's own flatPortParams()): unit,
// range and meaning, declared once; the default is the initialiser above.
std::span<const ParamDecl<PinaxConfig>> pinaxParams();

// False with a message naming the field when the port or the reference distance is outside its declared
// range.
bool validatePinaxConfig(const PinaxConfig& config, std::string* error);

// z of the virtual pinhole in the real camera frame: the middle of the spread of axis crossings of the
// rays up to max_theta_air_rad (the widest ray of the image), which halves the worst error compared with
// the paraxial crossing when d0 is not optimal.
double pinaxVirtualCentreZ(const FlatPort& port, double max_theta_air_rad);

// The real camera's normalised (undistorted) coordinates of what the virtual pinhole at z_virtual sees
// along dir_virtual (real camera axes): the point at the reference distance on that ray, projected
// exactly through the port. False when that point cannot be seen.
bool pinaxVirtualToRealNormalised(const PinaxConfig& config, double z_virtual, const Eigen::Vector3d& dir_virtual,
                                  Eigen::Vector2d* xy_real);

// Largest air angle from the axis among the four image corners of a calibrated camera.
double maxAirAngleRad(const cv::Matx33d& K, const cv::Mat& dist, cv::Size image_size);

// Focal scale of the virtual camera: virtual focal = real focal * scale, chosen so that the widest
// corner ray lands on the same pixel radius in both (the virtual image covers the real one's view).
double pinaxFocalScale(const PinaxConfig& config, double z_virtual, double max_theta_air_rad);

}  // namespace deepnav
