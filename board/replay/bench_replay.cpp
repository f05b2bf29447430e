#include "board/replay/bench_replay.h"
#include "board/replay/fusion_csv.h"
#include "board/replay/foreign_replay.h"

#include "board/config/recording_options.h"
#include "board/config/text_file.h"
#include "board/config/board_overrides.h"
#include "board/replay/output_file.h"
#include "board/replay/workspace_files.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "drivers/clock/monotonic_clock.h"
#include "board/loop/scheduler.h"
#include "drivers/buffers/spsc_ring.h"
#include "drivers/recording/recording_writer.h"
#include "drivers/recording/sample_codec.h"
#include "nav/metrics/trajectory_association.h"
#include "vision/pipeline/vision_pipeline.h"

namespace deepnav {
namespace {

constexpr const char* kBoardMetadata = "deepnav.board";

struct PendingVision {
  TimeUs available_us = 0;
  VisionResult result;
};

// State of one bench replay: the core, its sink, vision, and the tick clock of the recording.
struct BenchRun {
  VehicleSetup setup;
  RecordingWriter writer;
  FusionCsvSink sink{&writer};  // the core's sink: the writer, and the diagnostics kept for fusion.csv
  NavCore core;
  VisionPipeline vision;
  VisionContextSource context;
  SpscRing<PendingVision> pending;
  Scheduler scheduler;
  int nav_task = 0;
  int vision_task = 0;
  TimeUs next_tick_us = 0;
  bool ticking = false;
  ReplaySummary* summary = nullptr;
  TimeUs first_us = 0;
  TimeUs last_us = 0;
  bool any = false;
  ReplayTap* tap = nullptr;
  // The dead-reckoning run (markers.enabled false, vision.vo_mode none): no vision result can reach the
  // filter and the stage-1 map is never used (no panel, no stage 2), so the pairs are not processed.
  bool vision_off = false;
};

// The VO results VoFusion will be offered (it fuses in stage 2 only, the stage of the last tick), per
// source: VoFusion counts only their total.
void countVoOffers(BenchRun* run, const InputSample& sample) {
  const auto* v = std::get_if<VisionResult>(&sample);
  if (!v || !v->frame_ok || run->core.last().stage != NavStage::kOptimised) return;
  if (v->vo_orb.valid) ++run->summary->vo_offers.orb;
  if (v->vo_planes.valid) ++run->summary->vo_offers.planes;
}

// The stage-2 VO results of a vision result just consumed, with what VoFusion made of them.
void noteVoOutcomes(BenchRun* run, const InputSample& sample, bool stage2) {
  const auto* v = std::get_if<VisionResult>(&sample);
  if (!v || !v->frame_ok || !stage2) return;
  for (const VoMeasurement* vo : {&v->vo_orb, &v->vo_planes}) {
    if (vo->valid) run->summary->vo_offered.push_back({v->t_us, *vo, run->core.vo().lastOutcome(vo->source)});
  }
}

// Every input goes to the loop through the tap when there is one (fault injection on the bench).
void feed(BenchRun* run, const InputSample& sample) {
  countVoOffers(run, sample);
  const bool stage2 = run->core.last().stage == NavStage::kOptimised;
  if (run->tap) {
    run->tap->onInput(sample, &run->core);
  } else {
    run->core.consume(sample);
  }
  noteVoOutcomes(run, sample, stage2);
}

void noteFrameTruth(BenchRun* run, const FrameTruth& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = t.q_odom_left_cam.normalized().toRotationMatrix();
  T.translation() = t.p_left_cam_in_odom_m;
  run->summary->frame_truth.push_back({t.t_us, T});
}

bool initRun(const ReplayOptions& o, const ReplayEventSource& reader, const ReplayMetadata& metadata, BenchRun* run,
             std::string* error) {
  if (!loadReplaySetup(o.board_path, reader, o.input_path, &run->setup, error) ||
      !applyBoardOverrides(o.overrides, &run->setup, error)) {
    return false;
  }
  const BoardConfig& c = run->setup.config;
  const TaskSpec table[] = {
      {"nav", c.loop.rate_hz, c.loop.budget_us, false},
      {"vision", static_cast<int>(c.camera.rate_hz + 0.5), c.loop.vision_budget_us, true},
  };
  if (!run->scheduler.init(table, 2, c.loop.late_tick_tolerance, error)) return false;
  run->nav_task = run->scheduler.findTask("nav");
  run->vision_task = run->scheduler.findTask("vision");
  if (!prepareOutputDir(o.out_dir, error)) return false;
  RecordingOptions ro = recordingOptions(c);
  ro.record_images = o.record_images;
  if (!run->writer.open(o.out_dir + "/replay.mcap", ro, error)) return false;
  for (const auto& [name, values] : recordingMetadata(run->setup)) run->writer.recordMetadata(name, values);
  for (const auto& [name, values] : metadata) run->writer.recordMetadata(name, values);
  // The simulator's record (with the true panel pose) travels with the run, so that a replay of the
  // replay still scores against it.
  if (const auto* sim = reader.metadata(kTruthPanelMetadata)) run->writer.recordMetadata(kTruthPanelMetadata, *sim);
  if (!run->pending.allocate(static_cast<std::size_t>(c.buffers.vision_results))) {
    if (error) *error = "replay: cannot allocate the vision result queue";
    return false;
  }
  VisionPipelineConfig vision = visionConfig(run->setup);
  vision.stage_probe_for_test = o.vision_stage_probe;
  if (!run->vision.init(vision, error)) return false;
  run->vision_off = !c.markers.enabled && c.vision.modality.mode == VoMode::kNone;
  run->context.init(robotFromCamera(run->setup));
  if (!run->core.init(run->setup, &run->sink, error)) return false;
  // A run of `deepnav run` that started from its saved workspace (service.state_dir): its stage machine
  // knew that, so the reproduction must too (the recorded vision results carry the map's state).
  if (const auto* ws = reader.metadata("deepnav.workspace");
      reader.hasSolutions() && !o.rerun && ws && ws->count("restored") && ws->at("restored") == "true") {
    run->core.setWorkspaceRestored(true);
    run->summary->workspace_restored = true;
  }
  if (o.workspace_in.empty()) return true;
  if (!loadWorkspace(o.workspace_in, &run->vision.workspace(), error)) return false;
  run->core.setWorkspaceRestored(true);
  run->summary->workspace_restored = true;
  return true;
}

void noteTime(BenchRun* run, TimeUs t_us) {
  if (!run->any) run->first_us = t_us;
  run->any = true;
  run->last_us = std::max(run->last_us, t_us);
}

// The filter's own pose (the feedback, before the output smoother) at the time of its state, with its
// covariance, and the board's panel estimate.
ReplayTick tickRecord(const NavCore& core, const NavSolution& published) {
  const NavFeedback& f = core.feedback();
  const Ekf& ekf = core.ekf();
  ReplayTick r;
  r.stage = published.stage;
  r.panel_fixed = f.panel_fixed;
  r.T_odom_panel = f.T_odom_panel;
  // While the IMU is stale the solution coasts to the tick (Ekf::coast; the attitude is then not
  // flagged valid): its pose is the tick's, else the state's, at its last IMU sample.
  const bool coasting = !(published.status & kStatusAttitudeValid);
  r.filter_t_s = usToS(coasting ? published.t_us : ekf.state().t_us);
  r.p_filter_m = f.p_robot_in_odom_m;
  r.q_filter = f.q_odom_robot;
  r.P_position_m2 = published.cov_pose.block<3, 3>(0, 0);
  r.var_yaw_rad2 = published.cov_pose(5, 5);
  return r;
}

void tickAt(BenchRun* run, TimeUs t_us) {
  run->scheduler.recordTickStart(t_us, t_us);  // as fast as possible: a tick is never late
  if (run->tap) run->tap->beforeTick(t_us, &run->core);
  const TimeUs start = monotonicUs();
  const NavSolution& s = run->core.tick(t_us);
  run->scheduler.recordRun(run->nav_task, monotonicUs() - start);
  if (run->tap) run->tap->afterTick(s, run->core);
  run->context.push(run->core.feedback());
  const double dive_s = usToS(s.t_us - run->first_us);
  if ((s.status & kStatusPanelFixed) && run->summary->panel_fixed_at_s < 0) run->summary->panel_fixed_at_s = dive_s;
  if (s.stage == NavStage::kOptimised && run->summary->stage2_at_s < 0) run->summary->stage2_at_s = dive_s;
  // Before alignment the filter has no attitude: those epochs are neither a trajectory nor scored.
  if (s.stage != NavStage::kInit) {
    run->summary->estimate.push_back({usToS(s.t_us), s.p_robot_in_odom_m, s.q_odom_robot});
    run->summary->tick_records.push_back(tickRecord(run->core, s));
  }
  ++run->summary->ticks;
}

// Raw sensor log: synthesise the loop's ticks on the recording clock.
void advanceTicksTo(BenchRun* run, TimeUs t_us) {
  if (!run->ticking) {
    const TimeUs period = run->scheduler.periodUs();
    run->next_tick_us = (t_us / period) * period;
    run->ticking = true;
  }
  while (run->next_tick_us < t_us) {
    while (const PendingVision* p = run->pending.front()) {
      if (p->available_us > run->next_tick_us) break;
      feed(run, p->result);
      run->pending.pop();
    }
    tickAt(run, run->next_tick_us);
    run->next_tick_us += run->scheduler.periodUs();
  }
}

void noteFrame(BenchRun* run, const VisionContext& context, const VisionResult& r, TimeUs elapsed_us) {
  FrameStat f;
  f.t_s = usToS(r.t_us);
  f.stage = static_cast<int>(context.stage);
  f.image_quality = r.image_quality;
  f.selected = static_cast<int>(r.vo_selected);
  f.orb_vo = r.vo_orb.valid;
  f.planes_vo = r.vo_planes.valid;
  f.orb_tracked = r.orb_tracked;
  f.planes = r.planes;
  f.markers = r.marker_count;
  for (int i = 0; i < r.marker_count && i < VisionResult::kMaxMarkers && run->setup.has_panel; ++i) {
    if (const PanelMarker* m = run->setup.panel.marker(r.markers[static_cast<std::size_t>(i)].id)) {
      f.face = m->face;
      break;
    }
  }
  f.orb_us = r.orb_us;
  f.planes_us = r.planes_us;
  f.map_us = r.map_us;
  f.total_us = static_cast<std::uint32_t>(elapsed_us);
  run->summary->frame_stats.push_back(f);
}

void runVision(BenchRun* run, const StereoFrame& frame) {
  run->writer.recordFrame(frame, -1);
  PendingVision p;
  const TimeUs start = monotonicUs();
  const VisionContext context = run->context.contextAt(frame.t_us);
  run->vision.process(frame, context, &p.result);
  const TimeUs elapsed = monotonicUs() - start;
  noteFrame(run, context, p.result, elapsed);
  run->scheduler.recordRun(run->vision_task, elapsed);
  p.result.processing_us = static_cast<std::uint32_t>(elapsed);
  // Vision results reach the loop a fixed latency after capture, so the replay is deterministic.
  p.available_us = frame.t_us + static_cast<TimeUs>(run->setup.config.loop.vision_latency_ms) * 1000;
  run->pending.push(p);
  ++run->summary->frames;
}

bool onRerunEvent(BenchRun* run, const ReplayEvent& e) {
  switch (e.kind) {
    case ReplayEvent::Kind::kTruth:
      run->summary->truth.push_back({usToS(e.t_us), e.truth.p_robot_in_odom_m, e.truth.q_odom_robot});
      run->writer.recordTruth(e.truth);
      return true;
    case ReplayEvent::Kind::kSolution:
      return true;  // outputs of an earlier run: recomputed here
    case ReplayEvent::Kind::kFrameTruth:
      noteFrameTruth(run, *e.frame_truth);
      return true;
    case ReplayEvent::Kind::kFrame:
      noteTime(run, e.t_us);
      advanceTicksTo(run, e.t_us);
      if (run->vision_off) {
        ++run->summary->frames_not_processed;
        return true;
      }
      runVision(run, *e.frame);
      return true;
    case ReplayEvent::Kind::kInput:
      if (std::holds_alternative<VisionResult>(e.input)) return true;  // recomputed from the images
      noteTime(run, e.t_us);
      advanceTicksTo(run, e.t_us);
      feed(run, e.input);
      return true;
  }
  return true;
}

bool onReproduceEvent(BenchRun* run, const ReplayEvent& e) {
  switch (e.kind) {
    case ReplayEvent::Kind::kTruth:
      run->summary->truth.push_back({usToS(e.t_us), e.truth.p_robot_in_odom_m, e.truth.q_odom_robot});
      run->writer.recordTruth(e.truth);
      return true;
    case ReplayEvent::Kind::kFrame:
      run->writer.recordFrame(*e.frame, -1);
      ++run->summary->frames;
      return true;
    case ReplayEvent::Kind::kFrameTruth:
      noteFrameTruth(run, *e.frame_truth);
      return true;
    case ReplayEvent::Kind::kInput:
      noteTime(run, e.t_us);
      feed(run, e.input);
      return true;
    case ReplayEvent::Kind::kSolution: {
      noteTime(run, e.t_us);
      tickAt(run, e.solution.t_us);
      ++run->summary->solutions_compared;
      if (!sameBits(run->core.last(), e.solution)) ++run->summary->mismatches;
      return true;
    }
  }
  return true;
}

// Pairs a vision stage threw on: counted, the last exception named among the warnings and, for whoever
// reads the output recording, in its metadata "deepnav.vision_failures" (absent when none failed).
void noteVisionFailures(const VisionPipeline& vision, RecordingWriter* writer, ReplaySummary* summary) {
  summary->vision_failures = vision.failedPairs();
  if (summary->vision_failures == 0) return;
  const VisionStageFailure& f = vision.lastFailure();
  writer->recordMetadata("deepnav.vision_failures", {{"pairs", std::to_string(summary->vision_failures)},
                                                     {"last_pair", std::to_string(f.sequence)},
                                                     {"last_stage", visionStageName(f.stage)},
                                                     {"last_message", f.what}});
  summary->warnings.push_back(std::to_string(summary->vision_failures) +
                              " stereo pairs skipped: a vision stage threw (last: pair " + std::to_string(f.sequence) +
                              ", " + visionStageName(f.stage) + ": " + f.what + ")");
}

ModalityCount modalityCount(std::uint64_t offered, const SourceCounters& c) {
  ModalityCount m;
  m.offered = offered;
  m.fused = c.accepted;
  m.rejected_gate = c.rejected;
  m.rejected_other = offered > m.fused + m.rejected_gate ? offered - m.fused - m.rejected_gate : 0;
  m.gate_resets = c.gate_resets;
  return m;
}

ModalityCounts modalityCounts(const NavCore& core, const VoOffers& vo) {
  const Ekf& ekf = core.ekf();
  const InputCounters& in = core.counters();
  ModalityCounts m;
  m.dvl = modalityCount(in.dvl, ekf.health(kSrcDvl).counters);
  m.compass = modalityCount(in.heading, ekf.health(kSrcHeading).counters);
  m.depth = modalityCount(in.depth, ekf.health(kSrcDepth).counters);
  m.attitude = modalityCount(in.attitude, ekf.health(kSrcAttitude).counters);
  m.markers = modalityCount(core.markers().counters().fused, ekf.health(kSrcMarkers).counters);
  m.vo_orb = modalityCount(vo.orb, ekf.health(kSrcVoOrb).counters);
  m.vo_planes = modalityCount(vo.planes, ekf.health(kSrcVoPlanes).counters);
  return m;
}

}  // namespace

void computeReplayMetrics(ReplaySummary* s) {
  s->has_truth = !s->truth.empty() && !s->estimate.empty();
  std::vector<Eigen::Vector3d> positions;
  positions.reserve(s->estimate.size());
  for (const auto& p : s->estimate) positions.push_back(p.p_robot_in_odom_m);
  s->smoothness = smoothnessMa(positions);
  if (!s->has_truth) return;
  s->metrics = computeMetrics(s->estimate, s->tick_records, s->truth, s->truth_T_odom_panel);
  s->errors = s->metrics.odom.whole;
  std::sort(s->frame_truth.begin(), s->frame_truth.end(),
            [](const FrameTruthPose& a, const FrameTruthPose& b) { return a.t_us < b.t_us; });
  s->vo_consistency = computeVoConsistency(s->vo_offered, s->frame_truth);
}

// A recording with nothing to replay (cut off within its first records, or empty) is an error, not an
// empty result: the message names the file and, when it is cut off, where.
std::string replayNoDataError(const std::string& path, const ReplayEventSource& reader) {
  std::string why = path + ": holds no data to replay";
  if (!reader.truncated()) return why + " (no sensor sample, stereo pair or solution)";
  why += ": the file is truncated";
  if (!reader.warnings().empty()) why += " (" + reader.warnings().front() + ")";
  return why;
}

bool loadReplaySetup(const std::string& board_path, const ReplayEventSource& reader, const std::string& recording,
                     VehicleSetup* setup, std::string* error) {
  if (!board_path.empty()) return loadVehicleSetup(board_path, setup, error);
  bool found = false;
  if (!setupFromMetadata(reader.metadata(kBoardMetadata), reader.metadata("deepnav.panel"),
                         recording + " (stored board)", setup, error, &found,
                         reader.metadata(kCalibrationMetadata))) {
    return false;
  }
  if (found) return true;
  *setup = VehicleSetup{};
  setup->config = defaultBoardConfig();
  return true;
}

bool runBenchReplay(const ReplayOptions& o, ReplaySummary* summary, std::string* error) {
  if (!o.topics_path.empty()) return runForeignBenchReplay(o, summary, error);
  RecordingReader reader;
  if (!reader.open(o.input_path, error)) return false;
  reader.setDeliverFrameTruth(true);  // VO consistency (vo_consistency.h); the loop never sees it
  return runBenchReplayFrom(o, reader, nullptr, {}, summary, error);
}

bool runBenchReplayFrom(const ReplayOptions& o, ReplayEventSource& reader, const ReplayPrepare& prepare,
                        const ReplayMetadata& metadata, ReplaySummary* summary, std::string* error) {
  *summary = ReplaySummary{};
  auto run = std::make_unique<BenchRun>();
  run->summary = summary;
  run->tap = o.tap;
  if (!initRun(o, reader, metadata, run.get(), error)) return false;
  if (prepare && !prepare(run->setup, error)) return false;
  summary->reproduce = reader.hasSolutions() && !o.rerun;
  std::string panel_error;
  summary->truth_T_odom_panel = o.truth_T_odom_panel;
  if (!o.truth_T_odom_panel) {
    summary->truth_T_odom_panel = truthPanelFromMetadata(reader.metadata(kTruthPanelMetadata), &panel_error);
  }
  if (o.progress) {
    const std::string what = !o.topics_path.empty() ? "foreign recording through " + o.topics_path +
                                                          ": running the loop and vision on it"
                             : summary->reproduce ? "recorded run: re-running its ticks and comparing outputs"
                                                  : "sensor log: running the loop and vision on it";
    std::fprintf(stderr, "replay: %s (%s)\n", o.input_path.c_str(), what.c_str());
  }
  const TimeUs wall_start = monotonicUs();
  const bool ok = reader.forEach(
      !summary->reproduce,
      [&](const ReplayEvent& e) { return summary->reproduce ? onReproduceEvent(run.get(), e) : onRerunEvent(run.get(), e); },
      error);
  summary->wall_s = usToS(monotonicUs() - wall_start);
  if (ok && !run->any) {
    if (error) *error = replayNoDataError(o.input_path, reader);
    return false;
  }
  summary->dive_s = usToS(run->last_us - run->first_us);
  summary->inputs = run->core.counters();
  summary->markers = run->core.markers().counters();
  summary->panel = run->core.markers().panelEstimator().counters();
  summary->read = reader.stats();
  summary->warnings = reader.warnings();
  if (!panel_error.empty()) summary->warnings.push_back(panel_error);
  summary->loop = run->scheduler.stats();
  summary->vo = run->core.vo().counters();
  summary->modalities = modalityCounts(run->core, summary->vo_offers);
  summary->estimator_states = estimatorStatesReport(run->core.ekf());
  noteVisionFailures(run->vision, &run->writer, summary);
  summary->map_frames = run->vision.workspace().frames();
  summary->map_voxels = run->vision.workspace().voxels();
  if (!o.workspace_out.empty() && !summary->reproduce) {
    std::string ws_error;
    const auto& estimator = run->core.markers().panelEstimator();
    if (!estimator.fixed() || run->vision.workspace().voxels() == 0) {
      summary->warnings.push_back("workspace not saved: the panel was never fixed or the map is empty");
    } else if (!saveWorkspace(o.workspace_out, run->vision.workspace(),
                              run->core.markers().panelInOdom(run->core.ekf()), &ws_error)) {
      summary->warnings.push_back(ws_error);
    }
  }
  run->writer.recordLoopStats(run->last_us, summary->loop);
  std::string close_error;
  const bool closed = run->writer.close(&close_error);  // the message names the file and the reason
  if (!ok) return false;
  if (!closed) {
    if (error) *error = close_error;
    return false;
  }
  computeReplayMetrics(summary);
  return writeReplayOutputs(o.out_dir, *summary, error) &&
         writeFusionCsv(o.out_dir + "/fusion.csv", run->sink.rows(), error);
}

}  // namespace deepnav
