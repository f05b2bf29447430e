#include "nav/markers/marker_pose_covariance.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace deepnav {
namespace {

using D = ParamDecl<MarkerCovarianceConfig>;

const std::array kMarkerCovarianceParams = {
    D{"pos_floor_m", ParamType::kDouble, "m", 0, 1, "",
      "marker pose position 1-sigma at zero distance",
      DEEPNAV_PARAM_FIELD(MarkerCovarianceConfig, pos_floor_m)},
    D{"pos_per_d2_per_m", ParamType::kDouble, "1/m", 0, 1, "",
      "growth of the position 1-sigma with the squared distance",
      DEEPNAV_PARAM_FIELD(MarkerCovarianceConfig, pos_per_d2_per_m)},
    D{"rot_floor_rad", ParamType::kDouble, "rad", 0, 1, "",
      "marker pose rotation 1-sigma at zero distance",
      DEEPNAV_PARAM_FIELD(MarkerCovarianceConfig, rot_floor_rad)},
    D{"rot_per_d_rad_per_m", ParamType::kDouble, "rad/m", 0, 1, "",
      "growth of the rotation 1-sigma with distance",
      DEEPNAV_PARAM_FIELD(MarkerCovarianceConfig, rot_per_d_rad_per_m)},
};

bool fail(std::string* error, const char* message) {
  if (error) *error = message;
  return false;
}

}  // namespace

std::span<const ParamDecl<MarkerCovarianceConfig>> markerCovarianceParams() { return kMarkerCovarianceParams; }

bool validateMarkerCovarianceConfig(const MarkerCovarianceConfig& c, std::string* error) {
  if (!checkParamRanges(markerCovarianceParams(), c, "MarkerCovarianceConfig", "markers", error)) return false;
  if (!(c.pos_floor_m + c.pos_per_d2_per_m > 0.0) ||
      !(c.rot_floor_rad + c.rot_per_d_rad_per_m > 0.0)) {
    return fail(error, "pos_floor_m/rot_floor_rad: a zero model would give a zero covariance");
  }
  if (!(c.nominal_reprojection_px > 0.0))
    return fail(error, "nominal_reprojection_px: must be > 0");
  if (!(c.max_obliqueness_rad >= 0.0 && c.max_obliqueness_rad <= 1.5)) {
    return fail(error, "max_obliqueness_rad: must be in [0, 1.5]");
  }
  if (!(c.ambiguous_scale >= 1.0)) return fail(error, "ambiguous_scale: must be >= 1");
  return true;
}

MarkerPoseSigmas markerPoseSigmas(const MarkerObservation& obs, const MarkerCovarianceConfig& c) {
  const double d = obs.distance_m;
  const double k = 1.0 / std::cos(std::min(std::abs(obs.obliqueness_rad), c.max_obliqueness_rad));
  const double g = std::max(1.0, obs.reprojection_error_px / c.nominal_reprojection_px);
  MarkerPoseSigmas s;
  s.position_m = c.pos_floor_m + g * k * c.pos_per_d2_per_m * d * d;     // eq. (2)
  s.rotation_rad = c.rot_floor_rad + g * k * c.rot_per_d_rad_per_m * d;  // eq. (3)
  if (obs.ambiguous) {
    s.position_m *= c.ambiguous_scale;
    s.rotation_rad *= c.ambiguous_scale;
  }
  return s;
}

}  // namespace deepnav
