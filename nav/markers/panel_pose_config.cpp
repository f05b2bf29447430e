#include "nav/markers/panel_pose_config.h"

#include <numbers>

namespace deepnav {
namespace {

bool fail(std::string* error, const char* message) {
  if (error) *error = message;
  return false;
}

}  // namespace

bool validatePanelPoseConfig(const PanelPoseConfig& c, std::string* error) {
  if (c.min_observations < 1 || c.min_observations > 100000) {
    return fail(error, "min_observations: must be in [1, 100000]");
  }
  if (c.min_distinct_markers < 1 || c.min_distinct_markers > 4096) {
    return fail(error, "min_distinct_markers: must be in [1, 4096]");
  }
  if (!(c.max_position_std_m > 0.0)) return fail(error, "max_position_std_m: must be > 0");
  if (!(c.max_angle_std_rad > 0.0)) return fail(error, "max_angle_std_rad: must be > 0");
  if (!(c.max_distance_m > 0.0)) return fail(error, "max_distance_m: must be > 0");
  if (!(c.max_obliqueness_rad > 0.0 && c.max_obliqueness_rad <= 0.5 * std::numbers::pi)) {
    return fail(error, "max_obliqueness_rad: must be in (0, pi/2]");
  }
  if (!(c.max_reprojection_px > 0.0)) return fail(error, "max_reprojection_px: must be > 0");
  if (!(c.outlier_gate_sigma > 0.0)) return fail(error, "outlier_gate_sigma: must be > 0");
  if (!(c.outlier_floor_m > 0.0)) return fail(error, "outlier_floor_m: must be > 0");
  if (!(c.outlier_floor_rad > 0.0)) return fail(error, "outlier_floor_rad: must be > 0");
  if (c.restart_after_rejections < 1 || c.restart_after_rejections > 100000) {
    return fail(error, "restart_after_rejections: must be in [1, 100000]");
  }
  return true;
}

}  // namespace deepnav
