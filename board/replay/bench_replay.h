#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "board/loop/nav_core.h"
#include "board/replay/estimator_states_report.h"
#include "board/replay/replay_metrics.h"
#include "board/replay/replay_tap.h"
#include "board/replay/vo_consistency.h"
#include "drivers/replay/recording_reader.h"
#include "nav/metrics/smoothness.h"
#include "nav/metrics/stamped_pose.h"
#include "nav/metrics/trajectory_errors.h"
#include "nav/types/loop_stats.h"
#include "vision/pipeline/vision_pipeline.h"

namespace deepnav {

struct ReplayOptions {
  std::string input_path;
  std::string topics_path;       // a foreign recording (ROS 1 bag, ROS 2 MCAP) read through this topic map
  std::string out_dir;           // replay.mcap, trajectory.tum, truth.tum, summary.json
  std::string board_path;        // empty: the board stored in the recording, else the built-in defaults
  bool rerun = false;            // re-run vision and ticks from the sensors even if outputs are recorded
  bool record_images = false;    // copy the stereo images into replay.mcap
  bool progress = true;          // per-stage progress lines on stderr
  bool realtime = false;         // play at the recorded speed through the threaded runtime (realtime_replay.h)
  std::vector<std::string> overrides;  // board "key=value" overrides (board_overrides.h), e.g. vision.vo_mode=all
  std::string workspace_in;      // saved workspace to start from (stage 2 after the panel is found again)
  std::string workspace_out;     // where to save the workspace at the end (empty: not saved)
  ReplayTap* tap = nullptr;      // bench fault injection / observation of every input and tick (not owned)
  // Bench fault injection in the vision worker: VisionPipelineConfig::stage_probe_for_test (a stage that
  // throws as a library would). nullptr: none.
  void (*vision_stage_probe)(VisionStage stage) = nullptr;
  // The true panel pose in the recording's odometry frame for the panel-relative error; nullopt: the
  // recording's own (replay_metrics.h, kTruthPanelMetadata), if any.
  std::optional<Eigen::Isometry3d> truth_T_odom_panel;
};

// One stereo pair as the vision worker handled it (frames.csv; the report's Fig. 5 and Table III(a)).
struct FrameStat {
  double t_s = 0.0;
  int stage = 0;               // NavStage the worker saw
  double image_quality = -1.0;
  int selected = 0;            // VoSource chosen
  bool orb_vo = false;         // an ORB relative pose was produced
  bool planes_vo = false;      // a plane relative pose was produced
  int orb_tracked = 0;
  int planes = 0;
  int markers = 0;
  int face = -1;               // panel face of the first known marker seen (-1: none)
  std::uint32_t orb_us = 0, planes_us = 0, map_us = 0, total_us = 0;
};

struct ReplaySummary {
  bool reproduce = false;        // followed the recorded ticks (and compared the outputs)
  std::uint64_t ticks = 0;
  std::uint64_t frames = 0;
  std::uint64_t frames_not_processed = 0;  // dead-reckoning run: pairs read but given to no vision
  std::uint64_t vision_failures = 0;       // pairs failed by a throwing vision stage (skipped, not fused)
  std::uint64_t solutions_compared = 0;
  std::uint64_t mismatches = 0;  // recorded vs replayed NavSolution, bit for bit
  double dive_s = 0.0;           // recording time span
  double wall_s = 0.0;           // time the replay took
  InputCounters inputs;
  MarkerFusionCounters markers;      // marker observations and fused marker poses
  PanelPoseCounters panel;           // stage-1 panel pose estimation
  double panel_fixed_at_s = -1.0;    // dive time when the panel pose was fixed; -1: never
  double stage2_at_s = -1.0;         // dive time when stage 2 began; -1: never
  VoFusionCounters vo;               // VO relative poses offered to and fused by the EKF
  std::vector<FrameStat> frame_stats;
  bool workspace_restored = false;
  int map_frames = 0;
  int map_voxels = 0;
  ReplayReadStats read;
  LoopStats loop;
  std::vector<std::string> warnings;
  bool has_truth = false;
  TrajectoryErrors errors;       // estimate vs truth, per tick (= metrics.odom.whole)
  Smoothness smoothness;
  std::vector<StampedPose> estimate;  // published pose per tick after alignment of the filter
  std::vector<ReplayTick> tick_records;  // parallel to estimate: stage, panel estimate, filter pose and covariance
  std::vector<StampedPose> truth;
  std::optional<Eigen::Isometry3d> truth_T_odom_panel;
  ReplayMetrics metrics;             // panel-relative error, ATE, RPE, NEES (replay_metrics.h)
  VoOffers vo_offers;
  ModalityCounts modalities;
  std::vector<VoOffer> vo_offered;        // every stage-2 VO result offered, with its outcome
  std::vector<FrameTruthPose> frame_truth;  // true left-camera pose per pair (/truth/frame), if recorded
  VoConsistency vo_consistency;           // vo_offered scored against frame_truth (vo_consistency.h)
  EstimatorStatesReport estimator_states;  // the filter's sensor-error estimates at the end
};

// Replays a recording through the same NavCore as the vehicle, as fast as the machine goes:
//  - a recording of a run (it holds /nav/solution): inputs are fed in the order the loop consumed them
//    and each recorded tick is re-run; every output is compared bit for bit with the recorded one;
//  - a raw sensor log (e.g. from the simulator): ticks at the loop rate on the recording's clock, vision
//    run on each stereo pair and its result fused once `loop.vision_latency_ms` has passed.
// Writes the outputs to options.out_dir. False with a message naming the file on error.
// With options.topics_path, input_path is a foreign recording converted through the topic map
// (foreign_replay.h).
bool runBenchReplay(const ReplayOptions& options, ReplaySummary* summary, std::string* error);

// The same over any event source (opened by the caller). `prepare`, if set, runs once the setup is loaded
// (board, overrides), before the first event; `metadata` goes into the output recording with the setup's.
using ReplayPrepare = std::function<bool(const VehicleSetup& setup, std::string* error)>;
using ReplayMetadata = std::vector<std::pair<std::string, std::map<std::string, std::string>>>;
bool runBenchReplayFrom(const ReplayOptions& options, ReplayEventSource& source, const ReplayPrepare& prepare,
                        const ReplayMetadata& metadata, ReplaySummary* summary, std::string* error);

// The setup a replay runs with: board_path (and the panel file it names) if given, else the board and
// panel stored in the recording, else the built-in defaults without a panel.
bool loadReplaySetup(const std::string& board_path, const ReplayEventSource& reader, const std::string& recording,
                     VehicleSetup* setup, std::string* error);

// "<path>: holds no data to replay", and whether and where the file is cut off (reader.truncated()).
std::string replayNoDataError(const std::string& path, const ReplayEventSource& reader);

// Fills errors, smoothness and metrics from estimate, ticks and truth.
void computeReplayMetrics(ReplaySummary* summary);

// Writes summary.json, trajectory.tum, truth.tum, nees.csv and, with a panel-relative error,
// panel_trajectory.tum and panel_truth.tum (T_panel_robot) into dir.
bool writeReplayOutputs(const std::string& dir, const ReplaySummary& summary, std::string* error);

// The human-readable result table printed by `deepnav replay`.
std::string formatReplaySummary(const ReplaySummary& summary);

}  // namespace deepnav
