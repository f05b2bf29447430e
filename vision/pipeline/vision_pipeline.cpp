#include "vision/pipeline/vision_pipeline.h"

#include <algorithm>
#include <string>

namespace deepnav {

bool VisionPipeline::init(const VisionPipelineConfig& config, std::string* error) {
  if (config.width_px <= 0 || config.height_px <= 0) {
    if (error) *error = "vision: image size must be positive";
    return false;
  }
  config_ = config;
  return !config.detect_markers || detector_.init(config.markers, error);
}

void VisionPipeline::detectMarkers(const StereoFrame& frame, VisionResult* result) {
  if (!config_.detect_markers || !detector_.detect(frame.left, &observations_)) return;
  const int n = std::min<int>(observations_.count, VisionResult::kMaxMarkers);
  for (int i = 0; i < n; ++i) result->markers[static_cast<std::size_t>(i)] = observations_.items[static_cast<std::size_t>(i)];
  result->marker_count = n;
  result->markers_dropped = observations_.count - n + observations_.dropped;
}

void VisionPipeline::process(const StereoFrame& frame, VisionResult* result) {
  *result = VisionResult{};
  result->t_us = frame.t_us;
  result->sequence = frame.sequence;
  const bool size_ok = frame.left.cols == config_.width_px && frame.left.rows == config_.height_px &&
                       frame.right.size() == frame.left.size() && frame.right.type() == frame.left.type();
  MdmScore mdm;
  if (!size_ok || !computeMdm(frame.left, &mdm, &mdm_ws_)) return;
  result->frame_ok = true;
  result->mdm_f1 = mdm.f1;
  result->mdm_f2 = mdm.f2;
  result->mdm_f3 = mdm.f3;
  // Until the ORB VO reports its tracked-feature count, the quality is the MDM part of m_I alone.
  result->image_quality = mdm.score;
  detectMarkers(frame, result);
}

}  // namespace deepnav
