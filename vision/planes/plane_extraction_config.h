#pragma once

namespace deepnav {

// How regions are grown (PlaneExtractor): kTiles, the cell-based grower of Proenca & Gao (CAPE, IROS
// 2018): planar tiles grown over the tile graph, then the regions grown cell by cell from their whole
// tiles (PlaneTileGrower, the default: it passes the pixel grower's tests in half its instructions and
// the dives navigate the same, vision/planes/README.md); kPixels, the Poppinga grower below, point by
// point (PlaneRegionGrower, the reference).
enum class PlaneGrowingMethod { kPixels = 0, kTiles = 1 };

// Region growing after Poppinga, Vaskevicius, Birk & Pathak, "Fast plane detection and
// polygonalization in noisy 3D range images", IROS 2008, adapted to stereo noise. Areas and
// spacings are in image pixels, so a config holds at any cloud step (they are divided by step^2
// resp. step for the grid).
struct PlaneExtractionConfig {
  int max_planes = 32;        // capacity of the PlaneSet; growing stops when full (1..250)
  int min_area_px = 4000;     // a plane covers at least this many image pixels
  int seed_spacing_px = 16;   // seeds on a regular grid with this spacing
  int seed_window_cells = 5;  // a seed is a k x k patch of valid, free cells (odd, >= 3)
  // Point test (Poppinga's gamma), per candidate at depth Z:
  //   |n . p - d| <= max_point_distance_m + distance_sigmas * sigma,
  //   sigma = sigma_Z |d| / Z = Z * disparity_noise_px * |d| / (fx * B)
  // (stereo depth noise sigma_Z = Z^2 sigma_d / (f B) is along the ray; seen along the normal of
  // the plane n.p = d it shrinks by |n.p| / Z = |d| / Z).
  double max_point_distance_m = 0.005;
  double distance_sigmas = 2.5;
  // Local normal test: the normal of the cell's neighbourhood, (p[c+k] - p[c-k]) x (p[r+k] -
  // p[r-k]) with k cells ~ normal_span_m at the cell's depth (1..8), must be within
  // max_normal_angle_deg of the region's normal. Without it a region leaks along the line where its
  // (infinite) plane cuts another surface: those cells pass the distance test, and a box face grown
  // first cuts the floor in two with a thin band. Skipped where a neighbour at +-k is missing.
  double normal_span_m = 0.04;
  double max_normal_angle_deg = 45.0;
  // Region test (Poppinga's epsilon): mean squared point-to-plane distance of the region with the
  // candidate added, beyond the mean noise variance sigma^2 of its points.
  double max_mse_m2 = 0.0001;  // (1 cm)^2
  // The normal is refitted (3x3 eigen decomposition) whenever the region has grown by this
  // factor since the last fit; between fits the distance and MSE tests are O(1) per point.
  double refit_growth = 1.25;

  // Noise model for the plane covariance (Pathak et al. 2010): noise along the viewing ray from
  // the disparity noise, plus an isotropic floor (model error, texture). Variance of the residual
  // of point i: (Z_i * disparity_noise_px * d / (fx B))^2 + point_noise_floor_m^2.
  double disparity_noise_px = 0.3;
  double point_noise_floor_m = 0.002;
  // Correlated stereo errors (PlaneNoiseModel::independent_points): at most this many fitted cells count
  // as independent in the covariance; 0 = all of them (the size test still uses the full Hessian).
  double independent_points = 0.0;

  // Tile growing (growing == kTiles, PlaneTileGrower). A tile is tile_size_px x tile_size_px image
  // pixels (tile_size_px / step grid cells, at least 2); it is planar when at least
  // tile_min_valid_fraction of its cells hold a point and its mean squared distance to its own
  // plane, beyond the expected stereo noise, is at most max_mse_m2. A planar tile joins a region
  // when its normal is within tile_max_normal_angle_deg of the region's, its centroid passes the
  // point test above and the region's MSE with it passes the region test above.
  PlaneGrowingMethod growing = PlaneGrowingMethod::kTiles;
  int tile_size_px = 16;                   // 4..64
  double tile_min_valid_fraction = 0.5;    // (0, 1]
  double tile_max_normal_angle_deg = 20.0; // (0, 90]

  // Polygons
  int max_polygons = 256;
  int max_polygon_points = 65536;
  double min_hole_area_px = 64.0;  // smaller holes (noise) are not kept as polygons
};

}  // namespace deepnav
