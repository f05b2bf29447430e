#include "vision/orbvo/orb_vo_config.h"

namespace deepnav {

const char* OrbVoConfig::validate() const {
  if (pixel_sigma_px <= 0.0) return "pixel_sigma_px: must be > 0";
  if (right_budget_factor < 1.0 || right_budget_factor > 4.0)
    return "right_budget_factor: in [1, 4]";
  if (frame_search.radius_px <= 0.0 || map_search.radius_px <= 0.0)
    return "*_search.radius_px: must be > 0";
  if (frame_search_widen < 1.0) return "frame_search_widen: must be >= 1";
  if (local_keyframes < 2 || local_keyframes >= max_keyframes)
    return "local_keyframes: in [2, max_keyframes)";
  if (max_keyframes < 3 || max_keyframes > 4096) return "max_keyframes: in [3, 4096]";
  if (max_map_points < 100) return "max_map_points: must be >= 100";
  if (min_tracked < refiner.min_inliers) return "min_tracked: must be >= refiner.min_inliers";
  if (refiner.rounds < 1 || refiner.iterations < 1 || refiner.min_inliers < 4)
    return "refiner: rounds, iterations >= 1, min_inliers >= 4";
  if (bundle.iterations < 1) return "bundle.iterations: must be >= 1";
  if (pnp.iterations < 1 || pnp.reprojection_px <= 0.0 || pnp.confidence <= 0.0 ||
      pnp.confidence >= 1.0) {
    return "pnp: iterations >= 1, reprojection_px > 0, confidence in (0, 1)";
  }
  if (min_init_points < 10) return "min_init_points: must be >= 10";
  if (reloc.query_features < 10 || reloc.candidates < 1 ||
      reloc.min_inliers < refiner.min_inliers) {
    return "reloc: query_features >= 10, candidates >= 1, min_inliers >= refiner.min_inliers";
  }
  if (reloc.thumbnail_candidates < reloc.candidates) {
    return "reloc.thumbnail_candidates: must be >= reloc.candidates";
  }
  if (reloc.ratio <= 0.0 || reloc.ratio > 1.0) return "reloc.ratio: in (0, 1]";
  if (reset_after_lost_frames < 0) return "reset_after_lost_frames: must be >= 0";
  if (motion_prior.translation_sigma_m <= 0.0 || motion_prior.rotation_sigma_deg <= 0.0 ||
      motion_prior.consistency_chi2 <= 0.0 || motion_prior.gate_chi2 <= 0.0) {
    return "motion_prior: sigmas and chi-square gates must be > 0";
  }
  return "";
}

}  // namespace deepnav
