#include "vision/workspace/octree_lookup.h"

#include <algorithm>
#include <cmath>

namespace deepnav {
namespace {

// Smallest distance (in voxels) from any point of the voxel at the origin to the centre of the
// voxel at offset o: per axis max(0, |o| - 1/2).
double minOffsetDistance(const std::array<int, 3>& o) {
  double s = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double e = std::max(0.0, std::abs(o[k]) - 0.5);
    s += e * e;
  }
  return std::sqrt(s);
}

}  // namespace

bool OctreeLookup::build(const octomap::OcTree* tree, double distance_m) {
  if (tree == nullptr || distance_m < 0.0) return false;
  tree_ = tree;
  distance2_ = static_cast<float>(distance_m * distance_m);
  const double reach = distance_m / tree->getResolution();
  const int n = static_cast<int>(std::ceil(reach + 0.5));
  offsets_.clear();
  for (int x = -n; x <= n; ++x) {
    for (int y = -n; y <= n; ++y) {
      for (int z = -n; z <= n; ++z) {
        const std::array<int, 3> o{x, y, z};
        if (minOffsetDistance(o) <= reach) offsets_.push_back(o);
      }
    }
  }
  std::stable_sort(offsets_.begin(), offsets_.end(), [](const auto& a, const auto& b) {
    return minOffsetDistance(a) < minOffsetDistance(b);
  });
  return true;
}

bool OctreeLookup::isNear(const Eigen::Vector3f& p) const {
  octomap::OcTreeKey key;
  if (!tree_->coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), key)) return false;
  for (const auto& o : offsets_) {
    const int kx = key[0] + o[0], ky = key[1] + o[1], kz = key[2] + o[2];
    if (kx < 0 || ky < 0 || kz < 0 || kx > 0xFFFF || ky > 0xFFFF || kz > 0xFFFF) continue;
    const octomap::OcTreeKey k(static_cast<octomap::key_type>(kx),
                               static_cast<octomap::key_type>(ky),
                               static_cast<octomap::key_type>(kz));
    const octomap::OcTreeNode* node = tree_->search(k);
    if (node == nullptr || !tree_->isNodeOccupied(node)) continue;
    const octomap::point3d c = tree_->keyToCoord(k);
    const float dx = c.x() - p.x(), dy = c.y() - p.y(), dz = c.z() - p.z();
    if (dx * dx + dy * dy + dz * dz <= distance2_) return true;
  }
  return false;
}

}  // namespace deepnav
