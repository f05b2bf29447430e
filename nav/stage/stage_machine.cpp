#include "nav/stage/stage_machine.h"

#include <algorithm>

namespace deepnav {

bool StageMachine::init(const StageConfig& config, std::string* error) {
  if (!validateStageConfig(config, error)) return false;
  config_ = config;
  reset();
  return true;
}

void StageMachine::reset() {
  stage_ = NavStage::kInit;
  started_ = false;
  last_us_ = entered_us_ = workspace_us_ = 0;
  transitions_ = 0;
}

bool StageMachine::workspaceCriteriaMet(const StageInputs& in) const {
  if (!in.panel_fixed || !in.map_ready) return false;
  if (in.workspace_restored)
    return true;  // built in an earlier run: this run's criteria do not apply
  return workspace_us_ >= sToUs(config_.min_workspace_time_s) &&
         in.faces_seen_fraction >= config_.min_faces_seen_fraction;
}

NavStage StageMachine::next(const StageInputs& in) const {
  if (!in.filter_aligned) return NavStage::kInit;
  if (config_.stage2_without_panel && !in.has_panel) return NavStage::kOptimised;
  switch (stage_) {
    case NavStage::kInit:
      if (in.workspace_restored && in.panel_fixed && in.map_ready) return NavStage::kOptimised;
      return NavStage::kWorkspace;
    case NavStage::kWorkspace:
      return workspaceCriteriaMet(in) ? NavStage::kOptimised : NavStage::kWorkspace;
    case NavStage::kOptimised:
      return in.panel_fixed && in.map_ready ? NavStage::kOptimised : NavStage::kWorkspace;
  }
  return NavStage::kInit;
}

NavStage StageMachine::update(TimeUs t_us, const StageInputs& inputs) {
  if (!started_) {
    started_ = true;
    last_us_ = entered_us_ = t_us;
  }
  const TimeUs now_us = std::max(t_us, last_us_);
  // The time since the last update belongs to the stage we were in.
  if (stage_ == NavStage::kWorkspace) workspace_us_ += now_us - last_us_;
  last_us_ = now_us;
  const NavStage to = next(inputs);
  if (to != stage_) {
    if (stage_ == NavStage::kOptimised && to == NavStage::kWorkspace) workspace_us_ = 0;
    stage_ = to;
    entered_us_ = now_us;
    ++transitions_;
  }
  return stage_;
}

}  // namespace deepnav
