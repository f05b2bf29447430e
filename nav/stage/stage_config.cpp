#include "nav/stage/stage_config.h"

#include <array>

namespace deepnav {
namespace {

using D = ParamDecl<StageConfig>;

const std::array kStageParams = {
    D{"min_workspace_time_s", ParamType::kDouble, "s", 0, 86400, "",
      "time in stage 1 (workspace definition) before stage 2",
      DEEPNAV_PARAM_FIELD(StageConfig, min_workspace_time_s)},
    D{"min_faces_seen_fraction", ParamType::kDouble, "-", 0, 1, "",
      "fraction of the panel faces seen in stage 1 before stage 2",
      DEEPNAV_PARAM_FIELD(StageConfig, min_faces_seen_fraction)},
    D{"stage2_without_panel", ParamType::kBool, "-", 0, 0, "",
      "a run without a panel (marker-less rig, e.g. board/euroc) enters stage 2 (VO fused) once the filter is aligned "
      "(false: it stays in stage 1 and no VO is fused)",
      DEEPNAV_PARAM_FIELD(StageConfig, stage2_without_panel)},
};

}  // namespace

std::span<const ParamDecl<StageConfig>> stageParams() { return kStageParams; }

bool validateStageConfig(const StageConfig& c, std::string* error) {
  return checkParamRanges(stageParams(), c, "StageConfig", kStageSection, error);
}

}  // namespace deepnav
