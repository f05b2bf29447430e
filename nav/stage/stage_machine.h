#pragma once
#include <cstdint>
#include <string>

#include "nav/stage/stage_config.h"
#include "nav/types/nav_solution.h"
#include "nav/types/time.h"

namespace deepnav {

// What the stage machine looks at, sampled by the caller at each update.
struct StageInputs {
  bool filter_aligned = false;       // the EKF has its initial attitude (Ekf::aligned())
  bool panel_fixed = false;          // PanelPoseEstimator::fixed()
  bool map_ready = false;            // the workspace map is usable (decided by the map's owner)
  bool workspace_restored = false;   // panel pose and map were loaded from a saved workspace
  double faces_seen_fraction = 0.0;  // fraction of the panel's faces seen so far, [0, 1]
  bool has_panel = true;             // the run has a panel description (StageConfig::stage2_without_panel)
};

// The two-stage method as a state machine:
//   kInit       --aligned-->                                          kWorkspace
//   kInit       --aligned, panel fixed, map ready, restored-->        kOptimised   (restart from a
//   save) kWorkspace  --panel fixed, map ready, time in stage 1 >= min,
//                 faces seen >= min (or restored)-->                  kOptimised
//   kOptimised  --panel not fixed or map not ready-->                 kWorkspace   (caller reset
//   either) any         --not aligned-->                                      kInit        (filter
//   reset)
// Time in stage 1 is summed over every stay in kWorkspace since reset(), so an alignment loss does
// not restart it; a fall from stage 2 back to stage 1 does (a new workspace is being built). Time
// never runs backwards: an earlier t_us than the last counts as no time. Pure and deterministic.
class StageMachine {
 public:
  bool init(const StageConfig& config, std::string* error);
  void reset();  // back to kInit, time in stage 1 zero

  NavStage update(TimeUs t_us, const StageInputs& inputs);

  NavStage stage() const { return stage_; }
  TimeUs stageEnteredUs() const {
    return entered_us_;
  }  // t_us of the last transition (or first update)
  TimeUs workspaceTimeUs() const { return workspace_us_; }  // time spent in stage 1 (see above)
  std::uint32_t transitions() const { return transitions_; }
  const StageConfig& config() const { return config_; }

 private:
  NavStage next(const StageInputs& in) const;
  bool workspaceCriteriaMet(const StageInputs& in) const;

  StageConfig config_;
  NavStage stage_ = NavStage::kInit;
  bool started_ = false;
  TimeUs last_us_ = 0;
  TimeUs entered_us_ = 0;
  TimeUs workspace_us_ = 0;
  std::uint32_t transitions_ = 0;
};

}  // namespace deepnav
