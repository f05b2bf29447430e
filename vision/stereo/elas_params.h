#pragma once
#include "vision/stereo/disparity_edge_refiner.h"

namespace deepnav {

// Parameters of ElasDisparity. Names follow Geiger, Roser & Urtasun, "Efficient Large-Scale
// Stereo Matching", ACCV 2010. Defaults are for general use on low-texture
// scenes; nothing is tuned to a particular data set.
struct ElasParams {
  int num_disparities = 64;  // d in [0, num_disparities), at most 256

  // Descriptor: 3x3 Sobel responses scaled so that the 90th percentile of |gx| becomes
  // descriptor_target (of the +-127 an 8-bit descriptor byte holds), gain at most
  // max_descriptor_gain so that sensor noise of a flat frame is not blown up; fixed_descriptor_gain
  // > 0 replaces the automatic gain.
  float descriptor_target = 80.0f;
  float max_descriptor_gain = 4.0f;
  float fixed_descriptor_gain = 0.0f;

  // Support points: matched on a regular grid over the full disparity range.
  int support_step_px = 5;          // grid spacing
  int support_texture = 10;         // minimum descriptor texture (l1 norm about zero gradient)
  float support_ratio = 0.85f;      // best cost must be < ratio * second-best cost (uniqueness)
  int support_lr_threshold_px = 2;  // left-right agreement of a support match
  // A support point survives when at least incon_min_support others within incon_window_cells
  // grid cells have a disparity within incon_threshold_px of it (removes isolated outliers).
  int incon_window_cells = 5;
  int incon_threshold_px = 2;
  int incon_min_support = 5;
  // A support point is left out of the triangulation (but kept as a candidate) when its nearest
  // neighbours on the grid in all four directions, within redundant_window_cells, agree within
  // redundant_threshold_px: the plane through them already predicts it.
  int redundant_window_cells = 5;
  int redundant_threshold_px = 1;

  // Prior: p(d | S, o) ∝ gamma + exp(-(d - mu)^2 / (2 sigma^2)) within sradius_px of the
  // triangulated plane mu, or d one of the support disparities of the grid cell.
  int grid_size_px = 20;
  float beta = 0.02f;  // likelihood ∝ exp(-beta * l1 distance of descriptors)
  float gamma = 3.0f;
  float sigma_px = 1.0f;
  int sradius_px = 2;
  int match_texture = 1;  // pixels with less descriptor texture get no disparity

  // Post-processing
  int lr_threshold_px = 2;      // left-right consistency of the dense maps
  int speckle_size_px = 200;    // connected segments smaller than this are removed
  float speckle_sim_px = 1.0f;  // neighbours closer than this belong to one segment
  int ipol_gap_width_px = 3;    // gaps up to this width are interpolated along rows, columns
  bool fill_all = false;        // then fill every remaining hole from its background side
  bool subpixel = true;         // parabola through the costs at d-1, d, d+1
  // Edge-aware refinement (DisparityEdgeRefiner, beyond the paper): undoes the foreground
  // fattening of window matching at depth edges. refine.band_px = 0 disables it.
  EdgeRefineParams refine;

  // Robot preset: leave unmatched pixels invalid, fill small gaps only.
  static ElasParams robotics() { return ElasParams{}; }
  // Dense preset: every pixel gets a disparity (benchmarks that count holes as errors).
  static ElasParams dense() {
    ElasParams p;
    p.ipol_gap_width_px = 1 << 20;
    p.fill_all = true;
    return p;
  }
};

}  // namespace deepnav
