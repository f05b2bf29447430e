#pragma once
#include <span>
#include <string>

#include "base/param_decl.h"
#include "nav/types/time.h"
#include "vision/calib/stereo_rectification.h"
#include "vision/cloud/stereo_cloud.h"
#include "vision/markers/marker_detector.h"
#include "vision/orbvo/orb_vo_config.h"
#include "vision/orbvo/stereo_rig.h"
#include "vision/pipeline/modality_selector.h"
#include "vision/pipeline/workspace_model.h"
#include "vision/planes/plane_odometry.h"

namespace deepnav {

// Monotonic clock (us) for the per-part timing statistics; board/ supplies it.
using VisionClockUs = TimeUs (*)();

// The parts of the per-pair processing whose library calls (OpenCV above all) may throw.
enum class VisionStage : int { kRectify, kQuality, kMarkers, kOrb, kWorkspace, kStage2, kCount };
const char* visionStageName(VisionStage stage);

// Everything the vision worker (VisionPipeline) is configured with. The fields a board sets are declared
// once in visionPipelineParams() (key, unit, range, meaning); their defaults are the initialisers of the
// structs below (a board overrides two: board/config/board_config.cpp, kBoardDefaults). The image size, rig, markers and rectification come from the board's camera.* and the
// panel (board/config/vehicle_setup.h: visionConfig()).
struct VisionPipelineConfig {
  int width_px = 688;
  int height_px = 516;
  int channels = 1;
  // Raw frames (rectified = false) are remapped with these maps, built once at start-up by board/ (plain
  // pinhole or PinAx), before anything else runs; markers, rig and dense must then hold the rectified
  // intrinsics (rectification.rectified, baseline_m). Frames that arrive rectified are used as they are;
  // without maps every frame is taken as rectified with the rig's intrinsics (the board names no
  // calibration: the cameras deliver rectified images, whatever the driver marks them).
  bool rectify = false;
  StereoRectification rectification;
  bool detect_markers = false;   // when the vehicle has a panel description
  MarkerDetectorConfig markers;  // dictionary, marker size, rectified intrinsics
  StereoRig rig;                 // rectified intrinsics and baseline
  bool run_orb = true;           // ORB tracking on every pair (its count is part of m_I)
  OrbVoConfig orb;
  int orb_max_tracked = 300;     // tracked count that scores 1 in m_I
  ModalityConfig modality;
  StereoCloudConfig dense;       // dense stereo of the map and the plane VO
  bool filter_with_map = true;   // stage 2: the plane VO's cloud keeps only points near the map
  // ... unless fewer than this fraction would be kept: the view is then outside the mapped workspace.
  double map_min_kept_fraction = 0.3;
  PlaneOdometryConfig planes;
  WorkspaceBuildConfig workspace;
  VisionClockUs clock_us = nullptr;  // per-part timing in VisionResult; nullptr: zeros
  // Tests only: called at the start of every stage of every pair (inside its guard), to make a stage
  // throw as a library would. nullptr on the vehicle.
  void (*stage_probe_for_test)(VisionStage stage) = nullptr;
};

// The board keys of the vision worker (section kVisionSection of a board file), declared once: unit, range
// and meaning of the fields above a board sets. vision.vo_mode and vision.dense_method are choices that land
// in the enums VoMode and DenseStereoMethod (their order is the order of the choices).
inline constexpr const char* kVisionSection = "vision";
std::span<const ParamDecl<VisionPipelineConfig>> visionPipelineParams();

// The name a board file writes for a dense stereo method ("elas", "sgbm", "sgbm-wls").
std::string denseStereoMethodName(DenseStereoMethod method);

// False with a message naming the field and the key when a declared field is out of its range.
bool validateVisionPipelineConfig(const VisionPipelineConfig& config, std::string* error);

}  // namespace deepnav
