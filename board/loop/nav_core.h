#pragma once
#include <cstdint>
#include <string>

#include "board/config/vehicle_setup.h"
#include "drivers/recording/record_sink.h"
#include "nav/ekf/ekf.h"
#include "nav/pipeline/marker_fusion.h"
#include "nav/pipeline/pose_history.h"
#include "nav/pipeline/vo_fusion.h"
#include "nav/pipeline/output_smoother.h"
#include "board/loop/vision_context_source.h"
#include "nav/stage/stage_machine.h"
#include "nav/types/input_sample.h"
#include "nav/types/nav_solution.h"

namespace deepnav {

// Counters of what the loop consumed, by kind.
struct InputCounters {
  std::uint64_t imu = 0, dvl = 0, depth = 0, heading = 0, attitude = 0, vision = 0;
  std::uint64_t accepted = 0, rejected = 0, queued = 0, dropped_late = 0, bad_input = 0, not_aligned = 0;
  std::uint64_t refused = 0;  // refused by a source health check (the compass in a magnetic disturbance)
};

// The deterministic heart of the nav loop: every input it consumes is recorded and fed to the filter, and
// every tick produces one NavSolution, recorded too. It knows nothing of threads, clocks or files, so a
// live dive and a bench replay run exactly this code, and a replay of its recording reproduces its
// outputs bit for bit. No allocation after init().
class NavCore {
 public:
  NavCore() = default;
  NavCore(const NavCore&) = delete;
  NavCore& operator=(const NavCore&) = delete;

  bool init(const VehicleSetup& setup, RecordSink* sink, std::string* error);

  // One input, in consumption order. It is recorded before it is used.
  void consume(const InputSample& sample);

  // End of a loop tick at t_us: the solution of the filter, recorded and returned.
  const NavSolution& tick(TimeUs t_us);

  const NavSolution& last() const { return solution_; }
  const InputCounters& counters() const { return counters_; }
  const Ekf& ekf() const { return ekf_; }
  const MarkerFusion& markers() const { return markers_; }
  MarkerFusion& markers() { return markers_; }
  const VoFusion& vo() const { return vo_; }
  // What the vision worker needs after this tick (stage, pose, panel pose).
  const NavFeedback& feedback() const { return feedback_; }
  // A saved workspace was loaded: the stage machine may enter stage 2 without building a new map.
  void setWorkspaceRestored(bool restored) { workspace_restored_ = restored; }
  bool hasPanel() const { return has_panel_; }

 private:
  void count(FuseResult r);
  void consumeVision(const VisionResult& v);
  void recordEstimatorStates(TimeUs t_us);

  static constexpr TimeUs kEstimatorStatesPeriodUs = 1'000'000;

  Ekf ekf_;
  PoseHistory poses_;
  MarkerFusion markers_;
  VoFusion vo_;
  OutputSmoother smoother_;
  StageMachine stage_;
  NavFeedback feedback_;
  bool map_ready_ = false;
  bool workspace_restored_ = false;
  bool fuse_markers_in_stage2_ = true;
  bool has_panel_ = false;
  RecordSink* sink_ = nullptr;
  NavSolution solution_;
  InputCounters counters_;
  double image_quality_ = -1.0;
  TimeUs last_states_t_us_ = -1;  // last /nav/estimator_states record
};

}  // namespace deepnav
