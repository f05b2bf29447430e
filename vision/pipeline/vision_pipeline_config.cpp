#include "vision/pipeline/vision_pipeline_config.h"

#include <array>

namespace deepnav {
namespace {

using D = ParamDecl<VisionPipelineConfig>;

// The order of the choices is the order of the enums they land in (VoMode, DenseStereoMethod).
constexpr const char* kVoModes = "adaptive|all|orb|planes|none";
constexpr const char* kDenseStereoMethods = "elas|sgbm|sgbm-wls";
constexpr const char* kPlaneGrowingMethods = "pixels|tiles";  // PlaneGrowingMethod

const std::array kVisionParams = {
    D{"vo_mode", ParamType::kEnum, "-", 0, 0, kVoModes,
      "stage-2 visual odometry: adaptive (paper), all (both fused), orb, planes, none (T_L1)",
      DEEPNAV_PARAM_ENUM_FIELD(VisionPipelineConfig, modality.mode)},
    D{"quality_threshold", ParamType::kDouble, "-", 0, 1, "",
      "image quality m_I below which the plane VO runs instead of the ORB VO",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, modality.threshold)},
    D{"quality_hysteresis", ParamType::kDouble, "-", 0, 0.49, "",
      "m_I must cross threshold -/+ this to switch modality",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, modality.hysteresis)},
    D{"planes_when_orb_lost", ParamType::kBool, "-", 0, 0, "",
      "adaptive: run the plane VO on a pair the ORB VO could not track",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, modality.planes_when_orb_lost)},
    D{"orb_max_tracked", ParamType::kInt, "features", 1, 100000, "", "tracked ORB features that score 1 in m_I",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, orb_max_tracked)},
    // After a gap of frames the view has moved on and relocalisation against the old keyframes can fail
    // forever (fault_vision_test: no ORB result for the rest of the dive after 2 s of missing frames).
    D{"orb_reset_after_lost_frames", ParamType::kInt, "pairs", 0, 100000, "",
      "consecutive pairs the ORB VO failed to track or relocalise after which it starts a new map (0: never)",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, orb.reset_after_lost_frames)},
    D{"orb_motion_prior", ParamType::kBool, "-", 0, 0, "",
      "when the ORB VO's motion disagrees with the navigation's prediction since the last tracked pair (chi-square "
      "99.9 %), its inliers are re-selected around the prediction (coherently drifting marine snow falls outside); "
      "the pose and covariance still come from the images (vision/orbvo/motion_prior.h)",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, orb.motion_prior.enabled)},
    D{"markers_coarse_search", ParamType::kBool, "-", 0, 0, "",
      "marker detection searches a half-resolution image for quads and runs the full-resolution detector only "
      "around them: about 4x less CPU on dive frames, same corners, but misses some small far markers "
      "(vision/markers/coarse_marker_regions.h)",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, markers.coarse_search)},
    D{"dense_method", ParamType::kEnum, "-", 0, 0, kDenseStereoMethods,
      "dense stereo of the workspace map and the plane VO",
      DEEPNAV_PARAM_ENUM_FIELD(VisionPipelineConfig, dense.method)},
    D{"dense_scale_down", ParamType::kInt, "-", 1, 2, "", "images reduced by this factor before dense matching",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, dense.scale_down)},
    D{"dense_disparities", ParamType::kInt, "px", 16, 256, "", "dense disparity search range at the reduced size",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, dense.num_disparities)},
    D{"filter_with_map", ParamType::kBool, "-", 0, 0, "",
      "stage 2: keep only cloud points near the stage-1 workspace map",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, filter_with_map)},
    D{"map_min_kept_fraction", ParamType::kDouble, "-", 0, 1, "",
      "stage 2: when the map filter would keep less than this share of a cloud, the view lies outside the "
      "mapped workspace and the cloud is used unfiltered",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, map_min_kept_fraction)},
    D{"planes_covariance_scale", ParamType::kDouble, "-", 1, 1e8, "",
      "multiplies the plane registration covariance: the per-point stereo errors of window matching are "
      "correlated, so the independent-noise covariance is optimistic (on simulated dives the rotation errors "
      "were 30-100x the predicted sigma)",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, planes.registration.covariance_scale)},
    D{"planes_partial", ParamType::kBool, "-", 0, 0, "",
      "fuse single-plane registrations (two rotation axes, none about the normal)",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, planes.use_partial)},
    D{"planes_subspace", ParamType::kBool, "-", 0, 0, "",
      "plane registrations of degenerate sets give the directions they constrain (parallel planes: two rotation "
      "axes and the translation along the normal; two planes: the rotation and the translation in their span); "
      "the EKF fuses the constrained subspace only",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, planes.registration.subspace)},
    D{"planes_independent_points", ParamType::kDouble, "cells", 0, 1e6, "",
      "plane covariance: at most this many stereo cells of a plane count as independent measurements (dense "
      "stereo errors are correlated over a face: window overlap, support-point interpolation); 0: all cells",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, planes.extraction.independent_points)},
    D{"planes_growing", ParamType::kEnum, "-", 0, 0, kPlaneGrowingMethods,
      "plane extraction: tiles (planar tiles grown over the tile graph, then the regions grown cell by cell from "
      "their whole tiles, after CAPE: about 2x fewer instructions than pixels, not the same cells) or pixels "
      "(region growing point by point, the reference); vision/planes/README.md",
      DEEPNAV_PARAM_ENUM_FIELD(VisionPipelineConfig, planes.extraction.growing)},
    D{"planes_tile_size_px", ParamType::kInt, "px", 4, 64, "",
      "plane extraction with planes_growing=tiles: side of a tile in image pixels",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, planes.extraction.tile_size_px)},
    D{"map_resolution_m", ParamType::kDouble, "m", 0.01, 1, "", "workspace octomap leaf size",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, workspace.map.resolution_m)},
    D{"map_filter_distance_m", ParamType::kDouble, "m", 0.01, 2, "",
      "stage 2: points farther than this from every occupied voxel are removed",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, workspace.map.filter_distance_m)},
    D{"map_every_n_frames", ParamType::kInt, "frames", 1, 1000, "",
      "stage 1: one stereo pair in n is matched densely and inserted in the map",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, workspace.insert_every_n_frames)},
    D{"map_min_frames", ParamType::kInt, "frames", 0, 100000, "",
      "clouds inserted before the map is ready (stage 2 criterion)",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, workspace.min_frames)},
    D{"map_min_voxels", ParamType::kInt, "voxels", 0, 10000000, "",
      "occupied voxels before the map is ready (stage 2 criterion)",
      DEEPNAV_PARAM_FIELD(VisionPipelineConfig, workspace.min_voxels)},
};

}  // namespace

std::span<const ParamDecl<VisionPipelineConfig>> visionPipelineParams() { return kVisionParams; }

std::string denseStereoMethodName(DenseStereoMethod method) {
  return paramChoiceAt(kDenseStereoMethods, static_cast<int>(method));
}

bool validateVisionPipelineConfig(const VisionPipelineConfig& c, std::string* error) {
  return checkParamRanges(visionPipelineParams(), c, "VisionPipelineConfig", kVisionSection, error);
}

}  // namespace deepnav
