#pragma once
#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <vector>

#include "vision/cloud/organized_cloud.h"
#include "vision/workspace/grid_lookup.h"
#include "vision/workspace/kdtree_lookup.h"
#include "vision/workspace/octree_lookup.h"
#include "vision/workspace/workspace_config.h"

namespace deepnav {

// The workspace of the DexROV stage machine as an OctoMap (octomap::OcTree) in the odometry
// frame. Stage 1 inserts clouds at the estimated camera poses T_odom_cam; freeze() ends stage 1
// and builds the lookup; stage 2 filters every cloud to the points near occupied voxels. What is
// not part of the mapped workspace -- fish and other transients, and the comet-like streaks of
// mixed pixels at depth discontinuities, which lie in free space between foreground and
// background -- is removed before plane extraction.
//
// Occupancy: a voxel is occupied after min_hits frames hit it (threshold (min_hits - 1/2) l_hit
// in log-odds, one hit per voxel per frame). In kEndpoints mode nothing is ever cleared, so an
// object must stay put for min_hits frames to enter the map; kRayCast also clears.
//
// Allocation: the octree allocates nodes as it grows in stage 1 (OctoMap's design), freeze()
// allocates the lookup; filter() allocates nothing. Persistence is OctoMap's binary .bt format
// through a stream (the files themselves belong to board/): occupancy is kept as occupied/free,
// not as probabilities.
class WorkspaceMap {
 public:
  WorkspaceMap();
  ~WorkspaceMap();
  WorkspaceMap(const WorkspaceMap&) = delete;
  WorkspaceMap& operator=(const WorkspaceMap&) = delete;

  // Creates an empty map. Returns false for an invalid config.
  bool init(const WorkspaceConfig& config);

  // Stage 1. Returns false when frozen, uninitialised or the cloud is empty of grid.
  bool insert(const OrganizedCloud& cloud, const Eigen::Isometry3d& T_odom_cam);

  // End of stage 1: builds the configured lookup. False if the map holds more occupied voxels
  // than max_occupied_voxels or the grid would exceed max_grid_cells.
  bool freeze();
  // Builds another lookup (benchmarks, comparisons); the map must be frozen.
  bool buildLookup(WorkspaceLookupKind kind);
  void unfreeze();
  bool frozen() const { return frozen_; }

  // Stage 2. True when an occupied voxel centre is within filter_distance_m of p (GridLookup:
  // up to half a voxel diagonal more). False when that lookup is not built.
  bool isNear(const Eigen::Vector3f& p_point_in_odom_m) const;
  bool isNear(const Eigen::Vector3f& p_point_in_odom_m, WorkspaceLookupKind kind) const;
  // Invalidates the points of *cloud that are not near the map; returns how many were removed,
  // -1 when the map is not frozen or the lookup not built.
  int filter(const Eigen::Isometry3d& T_odom_cam, OrganizedCloud* cloud) const;
  int filter(const Eigen::Isometry3d& T_odom_cam, OrganizedCloud* cloud,
             WorkspaceLookupKind kind) const;

  // OctoMap binary (.bt) stream. read() replaces the map (resolution from the stream) and
  // leaves it unfrozen.
  bool write(std::ostream& out) const;
  bool read(std::istream& in);

  std::size_t occupiedVoxelCount() const;
  const octomap::OcTree& octree() const { return *tree_; }
  const WorkspaceConfig& config() const { return config_; }
  const GridLookup& gridLookup() const { return grid_; }

 private:
  void configureTree();
  bool collectOccupied();
  bool lookupBuilt(WorkspaceLookupKind kind) const;
  template <class Lookup>
  int filterWith(const Lookup& lookup, const Eigen::Isometry3d& T_odom_cam,
                 OrganizedCloud* cloud) const;

  bool ready_ = false;
  bool frozen_ = false;
  WorkspaceConfig config_;
  std::unique_ptr<octomap::OcTree> tree_;
  std::vector<std::uint64_t> keys_;   // packed voxel keys of one frame (endpoint mode)
  octomap::Pointcloud scan_;          // one frame in odom (ray-cast mode)
  std::vector<VoxelIndex> occupied_;  // at freeze
  std::vector<float> centres_xyz_;
  OctreeLookup octree_lookup_;
  KdTreeLookup kdtree_lookup_;
  GridLookup grid_;
  bool octree_built_ = false;
  bool kdtree_built_ = false;
  bool grid_built_ = false;
};

}  // namespace deepnav
