#include "vision/pipeline/vision_pipeline.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <string>

#include "vision/iqa/image_quality_score.h"

namespace deepnav {

namespace {

// Worker time of one part, for Table III(a), from the clock board/ hands in (none: 0). The outputs of the
// pipeline never depend on it.
class PartTimer {
 public:
  explicit PartTimer(VisionClockUs clock) : clock_(clock), start_us_(clock ? clock() : 0) {}
  std::uint32_t elapsedUs() const { return clock_ ? static_cast<std::uint32_t>(clock_() - start_us_) : 0u; }

 private:
  VisionClockUs clock_;
  TimeUs start_us_;
};

StereoGeometry geometryOf(const StereoRig& rig) {
  StereoGeometry g;
  g.fx_px = rig.fx_px;
  g.fy_px = rig.fy_px;
  g.cx_px = rig.cx_px;
  g.cy_px = rig.cy_px;
  g.baseline_m = rig.baseline_m;
  return g;
}

}  // namespace

bool VisionPipeline::init(const VisionPipelineConfig& config, std::string* error) {
  if (config.width_px <= 0 || config.height_px <= 0) {
    if (error) *error = "vision: image size must be positive";
    return false;
  }
  // The board's keys have the ranges declared in visionPipelineParams(); a config built in code too.
  if (!validateVisionPipelineConfig(config, error)) return false;
  config_ = config;
  config_.rig.width_px = config.width_px;
  config_.rig.height_px = config.height_px;
  config_.dense.channels = config.channels;
  frames_seen_ = 0;
  failed_pairs_ = 0;
  stage_failures_.fill(0);
  last_failure_ = VisionStageFailure{};
  if (config.rectify) {
    if (config.rectification.image_size != cv::Size(config.width_px, config.height_px)) {
      if (error) *error = "vision: the rectification maps do not have the camera's image size";
      return false;
    }
    if (!rectifier_.init(config.rectification, error) ||
        !allocateStereoFrame(rectified_, config.width_px, config.height_px, config.channels)) {
      if (error && error->empty()) *error = "vision: cannot allocate the rectified pair";
      return false;
    }
    rectified_.rectified = true;
  }
  if (config.detect_markers && !detector_.init(config.markers, error)) return false;
  if (config.run_orb && !orb_.init(config.orb, config_.rig, error)) return false;
  return selector_.init(config.modality, error) &&
         dense_.init(config_.dense, geometryOf(config_.rig), config.width_px, config.height_px, error) &&
         dense_.allocateCloud(&cloud_) && dense_.allocateCloud(&unfiltered_) &&
         plane_vo_.init(config.planes, dense_.geometry(), dense_.rows(), dense_.cols(), config.dense.cloud_step_px,
                        error) &&
         workspace_.init(config.workspace, error);
}

// The pair the rest of the pipeline sees: a raw frame remapped into rectified_ (same buffers every pair).
// Without maps the board declares the frames rectified (camera.* are their intrinsics), whatever the
// driver marked them: they are passed on as such (image headers only, no copy).
const StereoFrame& VisionPipeline::rectified(const StereoFrame& raw) {
  if (raw.rectified) return raw;
  if (!config_.rectify) {
    as_rectified_.t_us = raw.t_us;
    as_rectified_.exposure_us = raw.exposure_us;
    as_rectified_.sequence = raw.sequence;
    as_rectified_.left = raw.left;
    as_rectified_.right = raw.right;
    as_rectified_.rectified = true;
    return as_rectified_;
  }
  rectified_.t_us = raw.t_us;
  rectified_.exposure_us = raw.exposure_us;
  rectified_.sequence = raw.sequence;
  rectified_.rectified = rectifier_.rectify(raw.left, raw.right, rectified_.left, rectified_.right);
  return rectified_;
}

void VisionPipeline::detectMarkers(const StereoFrame& frame, VisionResult* result) {
  if (!config_.detect_markers || !detector_.detect(frame.left, &observations_)) return;
  const int n = std::min<int>(observations_.count, VisionResult::kMaxMarkers);
  for (int i = 0; i < n; ++i) result->markers[static_cast<std::size_t>(i)] = observations_.items[static_cast<std::size_t>(i)];
  result->marker_count = n;
  result->markers_dropped = observations_.count - n + observations_.dropped;
}

void VisionPipeline::runOrb(const StereoFrame& frame, const VisionContext& context, VisionResult* result) {
  if (!config_.run_orb) return;
  const PartTimer timer(config_.clock_us);
  if (context.has_pose) orb_.setMotionPrior(context.T_odom_cam);  // used with orb.motion_prior.enabled
  orb_.process(frame, &orb_out_);
  result->orb_us = timer.elapsedUs();
  result->orb_tracked = orb_out_.hasRelativePose() || orb_out_.status == OrbVoStatus::kInitialised
                            ? orb_out_.tracked_features
                            : 0;
}

void VisionPipeline::buildWorkspace(const StereoFrame& frame, const VisionContext& context, VisionResult* result) {
  const std::uint64_t index = frames_seen_;
  if (context.stage != NavStage::kWorkspace || !context.has_pose || !workspace_.wantsFrame(index)) return;
  const PartTimer timer(config_.clock_us);
  if (dense_.compute(frame.left, frame.right, &cloud_)) workspace_.insert(cloud_, context.T_odom_cam);
  result->map_us = timer.elapsedUs();
}

void VisionPipeline::runPlanes(const StereoFrame& frame, const VisionContext& context, VisionResult* result) {
  const PartTimer timer(config_.clock_us);
  bool ok = dense_.compute(frame.left, frame.right, &cloud_);
  if (ok && config_.filter_with_map) ok = filterByMap(context);
  if (ok && plane_vo_.process(frame.t_us, cloud_, &plane_out_)) result->vo_planes = plane_out_.vo;
  if (!ok) plane_vo_.reset();  // a frame without planes breaks the chain
  result->planes = ok ? plane_out_.planes : 0;
  result->planes_us = timer.elapsedUs();
}

// Stage 2's workspace filter. When it would remove nearly all of the cloud, the view is outside what
// stage 1 mapped (not a cloud of fish and streaks): the unfiltered cloud is used.
bool VisionPipeline::filterByMap(const VisionContext& context) {
  if (!context.has_pose) return false;
  const int before = cloud_.countValid();
  cloud_.p_point_in_cam_m.copyTo(unfiltered_.p_point_in_cam_m);
  const int removed = workspace_.filter(context.T_odom_cam, context.panel_fixed, context.T_odom_panel, &cloud_);
  if (removed < 0) return false;
  if (before > 0 && before - removed < config_.map_min_kept_fraction * before) {
    unfiltered_.p_point_in_cam_m.copyTo(cloud_.p_point_in_cam_m);
  }
  return true;
}

void VisionPipeline::runStage2(const StereoFrame& frame, const VisionContext& context, VisionResult* result) {
  if (context.stage != NavStage::kOptimised) {
    selector_.reset();
    plane_vo_.reset();
    return;
  }
  VoSource selected = selector_.select(result->image_quality);
  if (selected == VoSource::kOrb && config_.modality.mode == VoMode::kAdaptive &&
      config_.modality.planes_when_orb_lost && !(config_.run_orb && orb_out_.hasRelativePose())) {
    selected = VoSource::kPlanes;
  }
  result->vo_selected = selected;
  const bool all = config_.modality.mode == VoMode::kAll;
  if ((selected == VoSource::kOrb || all) && config_.run_orb && orb_out_.hasRelativePose()) {
    VoMeasurement& vo = result->vo_orb;
    vo.valid = true;
    vo.source = VoSource::kOrb;
    vo.t_reference_us = orb_out_.t_reference_us;
    vo.q_cama_camb = orb_out_.q_cama_camb;
    vo.p_camb_in_cama_m = orb_out_.p_camb_in_cama_m;
    vo.has_translation = true;
    vo.cov = orb_out_.cov;
    vo.support = orb_out_.tracked_features;
  }
  if (selector_.runPlanes(selected)) {
    runPlanes(frame, context, result);
  } else {
    plane_vo_.reset();
  }
}

const char* visionStageName(VisionStage stage) {
  switch (stage) {
    case VisionStage::kRectify: return "rectification";
    case VisionStage::kQuality: return "image quality";
    case VisionStage::kMarkers: return "markers";
    case VisionStage::kOrb: return "orb";
    case VisionStage::kWorkspace: return "workspace map";
    case VisionStage::kStage2: return "stage-2 vo";
    case VisionStage::kCount: break;
  }
  return "?";
}

// The one exception boundary of the worker: a try block costs nothing until something throws, and the
// stage that threw is the one stage_ names.
void VisionPipeline::process(const StereoFrame& input, const VisionContext& context, VisionResult* result) {
  *result = VisionResult{};
  result->t_us = input.t_us;
  result->sequence = input.sequence;
  stage_ = VisionStage::kRectify;
  try {
    processStages(input, context, result);
  } catch (const std::exception& e) {
    failPair(stage_, e.what(), result);
  } catch (...) {
    failPair(stage_, "unknown exception", result);
  }
}

void VisionPipeline::failPair(VisionStage stage, const char* what, VisionResult* result) {
  ++failed_pairs_;
  ++stage_failures_[static_cast<std::size_t>(stage)];
  last_failure_.stage = stage;
  last_failure_.sequence = result->sequence;
  std::snprintf(last_failure_.what, sizeof last_failure_.what, "%s", what ? what : "");
  const TimeUs t_us = result->t_us;
  const std::uint64_t sequence = result->sequence;
  *result = VisionResult{};  // nothing of a half-processed pair is fused
  result->t_us = t_us;
  result->sequence = sequence;
  // The state a stage left half updated is not trusted: the chains restart at the next pair.
  if (config_.run_orb) orb_.reset();
  plane_vo_.reset();
  selector_.reset();
  ++frames_seen_;
}

void VisionPipeline::processStages(const StereoFrame& input, const VisionContext& context, VisionResult* result) {
  const auto enter = [this](VisionStage stage) {
    stage_ = stage;
    if (config_.stage_probe_for_test) config_.stage_probe_for_test(stage);
  };
  const bool size_ok = input.left.cols == config_.width_px && input.left.rows == config_.height_px &&
                       input.right.size() == input.left.size() && input.right.type() == input.left.type();
  if (!size_ok) return;
  enter(VisionStage::kRectify);
  const StereoFrame& frame = rectified(input);
  if (config_.rectify && !frame.rectified) return;  // the remap refused the pair (image type)
  enter(VisionStage::kQuality);
  MdmScore mdm;
  if (!computeMdm(frame.left, &mdm, &mdm_ws_)) return;
  result->frame_ok = true;
  result->mdm_f1 = mdm.f1;
  result->mdm_f2 = mdm.f2;
  result->mdm_f3 = mdm.f3;
  enter(VisionStage::kMarkers);
  detectMarkers(frame, result);
  enter(VisionStage::kOrb);
  runOrb(frame, context, result);
  result->image_quality = config_.run_orb ? imageQualityScore(mdm, result->orb_tracked, config_.orb_max_tracked)
                                          : mdm.score;
  enter(VisionStage::kWorkspace);
  buildWorkspace(frame, context, result);
  enter(VisionStage::kStage2);
  runStage2(frame, context, result);
  result->map_frames = workspace_.frames();
  result->map_voxels = workspace_.voxels();
  result->map_ready = workspace_.ready();
  ++frames_seen_;
}

}  // namespace deepnav
