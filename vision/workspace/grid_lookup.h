#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "vision/workspace/voxel_key.h"

namespace deepnav {

// "Is p near the map?" as one bit test: a dense bitmap over the map's bounding box in which every
// voxel whose centre lies within distance + resolution * sqrt(3) / 2 of an occupied voxel centre
// is set (the map dilated by a ball, built once at freeze). The test is conservative: every point
// within distance of an occupied centre is accepted; a point may be accepted up to half a voxel
// diagonal farther (4.3 cm at 5 cm voxels). Memory: one bit per cell of the box.
class GridLookup {
 public:
  // occupied: voxel indices (voxel_key.h) of the occupied voxels. Fails when the bitmap would
  // exceed max_cells.
  bool build(const std::vector<VoxelIndex>& occupied, double resolution_m, double distance_m,
             std::size_t max_cells);
  bool isNear(const Eigen::Vector3f& p) const {
    const VoxelIndex v = voxelOf(p, inv_res_);
    const std::int64_t x = v.x - min_.x, y = v.y - min_.y, z = v.z - min_.z;
    if (x < 0 || y < 0 || z < 0 || x >= nx_ || y >= ny_ || z >= nz_) return false;
    const std::size_t i = static_cast<std::size_t>((z * ny_ + y) * nx_ + x);
    return (bits_[i >> 6] >> (i & 63)) & 1u;
  }
  std::size_t cellCount() const { return static_cast<std::size_t>(nx_) * ny_ * nz_; }
  std::size_t memoryBytes() const { return bits_.size() * sizeof(std::uint64_t); }

 private:
  std::vector<std::uint64_t> bits_;
  VoxelIndex min_;
  std::int64_t nx_ = 0, ny_ = 0, nz_ = 0;
  float inv_res_ = 1.0f;
};

}  // namespace deepnav
