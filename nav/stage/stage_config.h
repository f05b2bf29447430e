#pragma once
#include <span>
#include <string>

#include "base/param_decl.h"

namespace deepnav {

// Criteria of the stage machine (nav/stage/stage_machine.h), unit in the name, default here.
// Stage 2 needs the panel fixed and the caller's map-ready flag; these add criteria on how the
// workspace map was built in this run (they do not apply to a workspace restored from a saved panel
// pose and map).
struct StageConfig {
  double min_workspace_time_s = 30.0;    // time spent in stage 1 before stage 2
  double min_faces_seen_fraction = 0.5;  // fraction of the panel's faces seen in stage 1
  // A run without a panel (a marker-less rig) goes to stage 2 as soon as the filter is aligned: VO and
  // the navigation sensors alone, no workspace map. Off: without a panel the run stays in stage 1.
  bool stage2_without_panel = false;
};

// The board keys of the stage machine (section kStageSection): unit, range and meaning, declared once;
// the defaults are the initialisers above.
inline constexpr const char* kStageSection = "stage";
std::span<const ParamDecl<StageConfig>> stageParams();

// False with a message naming the key when a field is out of range.
bool validateStageConfig(const StageConfig& config, std::string* error);

}  // namespace deepnav
