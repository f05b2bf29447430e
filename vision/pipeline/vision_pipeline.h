#pragma once
#include <string>

#include "nav/types/vision_result.h"
#include "vision/iqa/mdm.h"
#include "vision/markers/marker_detector.h"
#include "vision/types/stereo_frame.h"

namespace deepnav {

struct VisionPipelineConfig {
  int width_px = 688;
  int height_px = 516;
  bool detect_markers = false;   // when the vehicle has a panel description
  MarkerDetectorConfig markers;  // dictionary, marker size, rectified intrinsics
};

// Per-stereo-pair processing of the vision worker: checks the frame, scores image quality, and (as the
// later stages land) detects markers and runs the selected visual odometry. Pure: the worker thread,
// the frame pool and the clock belong to board/. All buffers are sized in init().
class VisionPipeline {
 public:
  bool init(const VisionPipelineConfig& config, std::string* error);

  // Fills *result for one pair. Never throws; a bad frame gives frame_ok = false.
  void process(const StereoFrame& frame, VisionResult* result);

 private:
  VisionPipelineConfig config_{};
  void detectMarkers(const StereoFrame& frame, VisionResult* result);

  MdmWorkspace mdm_ws_{};
  MarkerDetector detector_;
  MarkerObservations observations_;
};

}  // namespace deepnav
