#pragma once
#include <cstddef>

namespace deepnav {

// How stage-1 clouds enter the map.
enum class WorkspaceInsertMode {
  // Ray-free: each frame's end points, one hit per voxel per frame, no free-space update. Fast
  // (no ray casting); transient objects (fish) and view-dependent mixed pixels stay out because a
  // voxel needs min_hits frames to become occupied.
  kEndpoints,
  // octomap insertPointCloud (discretised rays, max range): also clears free space, so a voxel
  // once hit by a passing fish is cleared by later rays through it. Several times slower.
  kRayCast,
};

// Which structure answers "is this point near the workspace?" once the map is frozen.
enum class WorkspaceLookupKind {
  kOctree,  // octree search at the point's leaf, then the leaves of its neighbourhood
  kKdTree,  // nanoflann kd-tree over the occupied voxel centres, any-within-radius query
  kGrid,    // dense bitmap of voxels near the map (dilated), one bit test per point
};

struct WorkspaceConfig {
  double resolution_m = 0.05;  // octree leaf size
  double max_range_m = 5.0;    // stage 1: points farther from the camera are not inserted
  int insert_step_cells = 2;   // stage 1: every n-th cloud cell in u and v is inserted
  WorkspaceInsertMode insert_mode = WorkspaceInsertMode::kEndpoints;
  int min_hits = 3;       // frames that must hit a voxel before it is occupied
  double prob_hit = 0.7;  // octomap sensor model
  double prob_miss = 0.4;
  // Stage 2: a point farther than this from every occupied voxel centre is not workspace.
  double filter_distance_m = 0.10;
  WorkspaceLookupKind lookup = WorkspaceLookupKind::kGrid;
  std::size_t max_cloud_points = 688 * 516;           // insertion buffer
  std::size_t max_occupied_voxels = 1u << 21;         // freeze() fails beyond
  std::size_t max_grid_cells = std::size_t{1} << 27;  // kGrid bitmap (16 MiB) limit
};

}  // namespace deepnav
