#pragma once
#include <Eigen/Core>
#include <cmath>
#include <cstdint>

namespace deepnav {

// Integer voxel coordinates of a point on the octree's lattice: voxel i spans
// [i * res, (i + 1) * res) on each axis, its centre is (i + 0.5) * res (octomap's keys are these
// plus 2^15).
struct VoxelIndex {
  std::int32_t x = 0, y = 0, z = 0;
};

inline VoxelIndex voxelOf(const Eigen::Vector3f& p, float inv_res) {
  return VoxelIndex{static_cast<std::int32_t>(std::floor(p.x() * inv_res)),
                    static_cast<std::int32_t>(std::floor(p.y() * inv_res)),
                    static_cast<std::int32_t>(std::floor(p.z() * inv_res))};
}

inline Eigen::Vector3f voxelCentre(const VoxelIndex& v, float res) {
  return Eigen::Vector3f((static_cast<float>(v.x) + 0.5f) * res,
                         (static_cast<float>(v.y) + 0.5f) * res,
                         (static_cast<float>(v.z) + 0.5f) * res);
}

}  // namespace deepnav
