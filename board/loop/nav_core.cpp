#include "board/loop/nav_core.h"

#include "base/overloaded.h"
#include "nav/ekf/systematic_states.h"

namespace deepnav {

bool NavCore::init(const VehicleSetup& setup, RecordSink* sink, std::string* error) {
  sink_ = sink;
  counters_ = InputCounters{};
  image_quality_ = -1.0;
  solution_ = NavSolution{};
  poses_.clear();
  // markers.enabled false: the loop runs as without a panel description (dead reckoning between fixes
  // of nothing: no panel pose, no marker robot pose, stage 1 throughout).
  has_panel_ = setup.has_panel && setup.config.markers.enabled;
  feedback_ = NavFeedback{};
  map_ready_ = false;
  workspace_restored_ = false;
  const BoardConfig& c = setup.config;
  fuse_markers_in_stage2_ = c.stage.fuse_markers_in_stage2;
  // As many pair clones as the EKF holds (less the panel's anchor when the filter holds the panel): when
  // full, the oldest is released before the new pair is cloned.
  const bool panel_in_filter = has_panel_ && c.markers.panel_in_filter;
  if (panel_in_filter && c.ekf.max_clones < 2) {
    if (error) *error = "markers.panel_in_filter: needs an EKF with at least 2 clones (one for the panel)";
    return false;
  }
  vo_.init(robotFromCamera(setup), c.ekf.max_clones - (panel_in_filter ? 1 : 0));
  smoother_.init(c.loop.output_tau_s);
  if (!stage_.init(c.stage.machine, error) || !ekf_.init(c.ekf, error)) return false;
  if (!has_panel_) return true;
  if (!markers_.init(setup.panel, robotFromCamera(setup), c.markers.panel_pose, c.markers.covariance, error)) {
    return false;
  }
  markers_.holdPanelInFilter(panel_in_filter);
  return true;
}

void NavCore::count(FuseResult r) {
  switch (r.status) {
    case FuseStatus::kAccepted: ++counters_.accepted; break;
    case FuseStatus::kRejected: ++counters_.rejected; break;
    case FuseStatus::kQueued: ++counters_.queued; break;
    case FuseStatus::kDroppedLate: ++counters_.dropped_late; break;
    case FuseStatus::kBadInput: ++counters_.bad_input; break;
    case FuseStatus::kNotAligned: ++counters_.not_aligned; break;
    case FuseStatus::kRefused: ++counters_.refused; break;
  }
}

void NavCore::consumeVision(const VisionResult& v) {
  ++counters_.vision;
  // A result of a pair older than the delay window cannot be fused (nor its pair cloned): a late drop,
  // counted here once per result, as a late sensor sample is.
  if (ekf_.beyondWindow(v.t_us)) ++counters_.dropped_late;
  if (v.frame_ok && v.image_quality >= 0.0) image_quality_ = v.image_quality;
  if (v.frame_ok) map_ready_ = v.map_ready;
  const bool stage2 = stage_.stage() == NavStage::kOptimised;
  if (has_panel_) markers_.onVision(v, poses_, &ekf_, !stage2 || fuse_markers_in_stage2_);
  vo_.onVision(v, stage2, &ekf_);
}

// Every kind is named: a new sample kind does not compile until it is routed here.
void NavCore::consume(const InputSample& sample) {
  if (sink_) sink_->recordInput(sample);
  std::visit(Overloaded{[this](const ImuSample& s) {
                          ++counters_.imu;
                          ekf_.setImu(s);
                        },
                        [this](const DvlSample& s) {
                          ++counters_.dvl;
                          count(ekf_.fuseDvl(s));
                        },
                        [this](const HeadingSample& s) {
                          ++counters_.heading;
                          count(ekf_.fuseHeading(s));
                        },
                        [this](const AttitudeSample& s) {
                          ++counters_.attitude;
                          count(ekf_.fuseAttitude(s));
                        },
                        [this](const DepthSample& s) {
                          ++counters_.depth;
                          count(ekf_.fuseDepth(s));
                        },
                        [this](const VisionResult& v) { consumeVision(v); }},
             sample);
}

// The sensor-error estimates once a second, when the board estimates any systematic state.
void NavCore::recordEstimatorStates(TimeUs t_us) {
  if (sink_ == nullptr || !ekf_.aligned() || ekf_.state().sys_layout.dim == 0) return;
  if (last_states_t_us_ >= 0 && t_us - last_states_t_us_ < kEstimatorStatesPeriodUs) return;
  last_states_t_us_ = t_us;
  sink_->recordEstimatorStates(estimatorStates(ekf_.state(), t_us));
}

const NavSolution& NavCore::tick(TimeUs t_us) {
  ekf_.noteLoopTime(t_us);
  solution_ = ekf_.solution(t_us);
  // The fusions since the last tick (nav/ekf/fusion_diagnostic.h), before this tick's solution.
  for (int i = 0; sink_ != nullptr && i < ekf_.diagnostics().size(); ++i) sink_->recordFusion(ekf_.diagnostics().at(i));
  ekf_.clearDiagnostics();
  recordEstimatorStates(t_us);
  if (ekf_.aligned()) poses_.push(solution_.t_us, solution_.p_robot_in_odom_m, solution_.q_odom_robot);
  // The solution is stamped with the tick; the filter state it holds is that of the last IMU sample
  // (at most one IMU period older at 100 Hz).
  solution_.t_us = t_us;
  solution_.image_quality = image_quality_;
  StageInputs in;
  in.filter_aligned = ekf_.aligned();
  in.panel_fixed = has_panel_ && markers_.panelFixed();
  in.map_ready = map_ready_;
  in.workspace_restored = workspace_restored_;
  in.faces_seen_fraction = has_panel_ ? markers_.facesSeenFraction() : 0.0;
  in.has_panel = has_panel_;
  solution_.stage = stage_.update(t_us, in);
  if (in.panel_fixed) solution_.status |= kStatusPanelFixed;
  feedback_.t_us = t_us;
  feedback_.has_pose = ekf_.aligned();
  feedback_.p_robot_in_odom_m = solution_.p_robot_in_odom_m;
  feedback_.q_odom_robot = solution_.q_odom_robot;
  feedback_.stage = solution_.stage;
  feedback_.panel_fixed = in.panel_fixed;
  if (in.panel_fixed) feedback_.T_odom_panel = markers_.panelInOdom(ekf_);
  smoother_.apply(&solution_);  // after the feedback: the vision worker and markers use the EKF's pose
  if (sink_) sink_->recordSolution(solution_);
  return solution_;
}

}  // namespace deepnav
