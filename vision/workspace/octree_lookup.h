#pragma once
#include <octomap/OcTree.h>

#include <Eigen/Core>
#include <array>
#include <vector>

namespace deepnav {

// "Is there an occupied voxel centre within distance of p?" answered on the octree itself: the
// leaf containing p first, then the leaves of its neighbourhood, nearest first. The neighbourhood
// (voxel offsets whose centre can be within distance of some point of p's voxel) is tabulated
// once; each candidate costs one octree descent (OcTree::search, up to 16 levels). A point near
// the map usually stops at its own or an adjacent leaf; a point far from it pays for the whole
// neighbourhood (81 descents for distance = 2 * resolution).
class OctreeLookup {
 public:
  bool build(const octomap::OcTree* tree, double distance_m);
  bool isNear(const Eigen::Vector3f& p) const;

 private:
  const octomap::OcTree* tree_ = nullptr;
  float distance2_ = 0.0f;
  std::vector<std::array<int, 3>> offsets_;
};

}  // namespace deepnav
