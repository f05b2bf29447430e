#pragma once
#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>

#include "nav/types/vision_result.h"
#include "vision/calib/stereo_rectification.h"
#include "vision/cloud/stereo_cloud.h"
#include "vision/iqa/mdm.h"
#include "vision/markers/marker_detector.h"
#include "vision/orbvo/orb_stereo_odometry.h"
#include "vision/orbvo/orb_vo_config.h"
#include "vision/orbvo/stereo_rig.h"
#include "vision/pipeline/modality_selector.h"
#include "vision/pipeline/vision_context.h"
#include "vision/pipeline/vision_pipeline_config.h"
#include "vision/pipeline/workspace_model.h"
#include "vision/planes/plane_odometry.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

// Why the last failed pair failed: its stage and the exception's message (truncated), kept in place so
// that recording it allocates nothing.
struct VisionStageFailure {
  VisionStage stage = VisionStage::kCount;
  std::uint64_t sequence = 0;  // of the pair
  char what[160] = {};
};

// Per-stereo-pair processing of the vision worker, the paper's method on one pair:
//   always: frame check, MDM, marker detection, ORB tracking (tracked count -> m_I);
//   stage 1: every n-th pair, dense stereo -> cloud inserted in the workspace map at the camera pose;
//   stage 2: modality selection on m_I; the ORB relative pose, or dense stereo -> cloud filtered by
//            the map -> planes -> registration; both in the "all" mode.
// Pure: the worker thread, the frame pool, the clock and the pose source belong to board/. All buffers
// are sized in init(); the stage-1 octree grows within its configured bounds.
class VisionPipeline {
 public:
  bool init(const VisionPipelineConfig& config, std::string* error);

  // Fills *result for one pair. Never throws; a bad frame gives frame_ok = false. A raw frame is first
  // rectified into the pipeline's own preallocated pair (config.rectify). A stage that throws (a library
  // precondition, e.g. OpenCV's StereoSGBM with a disparity range as wide as the image) fails the pair:
  // it is counted (failedPairs(), lastFailure()), its result is frame_ok = false (nothing of it is fused)
  // and the chains that span pairs (ORB map, plane VO, modality) restart at the next pair.
  void process(const StereoFrame& frame, const VisionContext& context, VisionResult* result);

  WorkspaceModel& workspace() { return workspace_; }
  const WorkspaceModel& workspace() const { return workspace_; }
  const StereoCloud& dense() const { return dense_; }
  StereoCloud& dense() { return dense_; }  // tools: one pair through the dense chain
  // Pairs failed by an exception in one of their stages, in total and per stage, and the last failure.
  std::uint64_t failedPairs() const { return failed_pairs_; }
  std::uint64_t stageFailures(VisionStage stage) const { return stage_failures_[static_cast<std::size_t>(stage)]; }
  const VisionStageFailure& lastFailure() const { return last_failure_; }

 private:
  const StereoFrame& rectified(const StereoFrame& frame);
  void detectMarkers(const StereoFrame& frame, VisionResult* result);
  void runOrb(const StereoFrame& frame, const VisionContext& context, VisionResult* result);
  void buildWorkspace(const StereoFrame& frame, const VisionContext& context, VisionResult* result);
  void runStage2(const StereoFrame& frame, const VisionContext& context, VisionResult* result);
  void runPlanes(const StereoFrame& frame, const VisionContext& context, VisionResult* result);
  bool filterByMap(const VisionContext& context);
  void processStages(const StereoFrame& input, const VisionContext& context, VisionResult* result);
  void failPair(VisionStage stage, const char* what, VisionResult* result);

  VisionPipelineConfig config_{};
  StereoRectifier rectifier_;
  StereoFrame rectified_;     // the remapped pair, preallocated in init()
  StereoFrame as_rectified_;  // no maps: the driver's raw-marked pair, declared rectified by the board
  MdmWorkspace mdm_ws_{};
  MarkerDetector detector_;
  MarkerObservations observations_;
  OrbStereoOdometry orb_;
  OrbVoOutput orb_out_;
  ModalitySelector selector_;
  StereoCloud dense_;
  OrganizedCloud cloud_;
  OrganizedCloud unfiltered_;  // the cloud before the map filter (same grid)
  PlaneOdometry plane_vo_;
  PlaneOdometryOutput plane_out_;
  WorkspaceModel workspace_;
  std::uint64_t frames_seen_ = 0;
  std::uint64_t failed_pairs_ = 0;
  std::array<std::uint64_t, static_cast<std::size_t>(VisionStage::kCount)> stage_failures_{};
  VisionStageFailure last_failure_;
  VisionStage stage_ = VisionStage::kRectify;  // the stage running (which one threw)
};

}  // namespace deepnav
