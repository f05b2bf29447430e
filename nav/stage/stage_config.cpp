#include "nav/stage/stage_config.h"

namespace deepnav {

bool validateStageConfig(const StageConfig& c, std::string* error) {
  if (!(c.min_workspace_time_s >= 0.0 && c.min_workspace_time_s <= 86400.0)) {
    if (error) *error = "min_workspace_time_s: must be in [0, 86400]";
    return false;
  }
  if (!(c.min_faces_seen_fraction >= 0.0 && c.min_faces_seen_fraction <= 1.0)) {
    if (error) *error = "min_faces_seen_fraction: must be in [0, 1]";
    return false;
  }
  return true;
}

}  // namespace deepnav
