#include "nav/markers/panel_pose_config.h"

#include <array>
#include <numbers>

namespace deepnav {
namespace {

using D = ParamDecl<PanelPoseConfig>;

const std::array kPanelPoseParams = {
    D{"panel_min_observations", ParamType::kInt, "-", 1, 100000, "",
      "marker observations before the panel pose can be fixed",
      DEEPNAV_PARAM_FIELD(PanelPoseConfig, min_observations)},
    D{"panel_min_distinct_markers", ParamType::kInt, "-", 1, 4096, "",
      "distinct markers before the panel pose can be fixed",
      DEEPNAV_PARAM_FIELD(PanelPoseConfig, min_distinct_markers)},
    D{"panel_max_position_std_m", ParamType::kDouble, "m", 0.001, 10, "",
      "position scatter below which the panel pose is fixed",
      DEEPNAV_PARAM_FIELD(PanelPoseConfig, max_position_std_m)},
    D{"panel_max_angle_std_rad", ParamType::kDouble, "rad", 0.0001, 1, "",
      "rotation scatter below which the panel pose is fixed",
      DEEPNAV_PARAM_FIELD(PanelPoseConfig, max_angle_std_rad)},
    D{"max_distance_m", ParamType::kDouble, "m", 0.1, 50, "",
      "markers farther than this are not used for the panel pose",
      DEEPNAV_PARAM_FIELD(PanelPoseConfig, max_distance_m)},
};

bool fail(std::string* error, const char* message) {
  if (error) *error = message;
  return false;
}

}  // namespace

std::span<const ParamDecl<PanelPoseConfig>> panelPoseParams() { return kPanelPoseParams; }

bool validatePanelPoseConfig(const PanelPoseConfig& c, std::string* error) {
  if (!checkParamRanges(panelPoseParams(), c, "PanelPoseConfig", kMarkersSection, error)) return false;
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
