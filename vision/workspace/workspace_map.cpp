#include "vision/workspace/workspace_map.h"

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>

namespace deepnav {
namespace {

constexpr int kTreeMaxVal = 32768;  // octomap key of coordinate 0

std::uint64_t packKey(const octomap::OcTreeKey& k) {
  return std::uint64_t{k[0]} | (std::uint64_t{k[1]} << 16) | (std::uint64_t{k[2]} << 32);
}

octomap::OcTreeKey unpackKey(std::uint64_t p) {
  return octomap::OcTreeKey(static_cast<octomap::key_type>(p & 0xFFFF),
                            static_cast<octomap::key_type>((p >> 16) & 0xFFFF),
                            static_cast<octomap::key_type>((p >> 32) & 0xFFFF));
}

}  // namespace

WorkspaceMap::WorkspaceMap() = default;
WorkspaceMap::~WorkspaceMap() = default;

bool WorkspaceMap::init(const WorkspaceConfig& config) {
  ready_ = false;
  if (!(config.resolution_m > 0.0) || !(config.max_range_m > 0.0) || config.insert_step_cells < 1 ||
      config.min_hits < 1 || !(config.prob_hit > 0.5 && config.prob_hit < 1.0) ||
      !(config.prob_miss > 0.0 && config.prob_miss < 0.5) || !(config.filter_distance_m >= 0.0) ||
      config.max_cloud_points == 0) {
    return false;
  }
  config_ = config;
  tree_ = std::make_unique<octomap::OcTree>(config.resolution_m);
  configureTree();
  keys_.assign(config.max_cloud_points, 0u);
  scan_.clear();
  scan_.reserve(config.max_cloud_points);
  unfreeze();
  ready_ = true;
  return true;
}

// Occupied after min_hits hits: threshold halfway between min_hits - 1 and min_hits hits; the
// upper clamp one hit above min_hits, so a long-seen voxel stays responsive to misses.
void WorkspaceMap::configureTree() {
  tree_->setProbHit(config_.prob_hit);
  tree_->setProbMiss(config_.prob_miss);
  const double l_hit = octomap::logodds(config_.prob_hit);
  tree_->setOccupancyThres(octomap::probability((config_.min_hits - 0.5) * l_hit));
  tree_->setClampingThresMax(octomap::probability((config_.min_hits + 1.0) * l_hit));
}

bool WorkspaceMap::insert(const OrganizedCloud& cloud, const Eigen::Isometry3d& T_odom_cam) {
  if (!ready_ || frozen_) return false;
  const Eigen::Matrix3f R = T_odom_cam.linear().cast<float>();
  const Eigen::Vector3f t = T_odom_cam.translation().cast<float>();
  const float range2 = static_cast<float>(config_.max_range_m * config_.max_range_m);
  const bool rays = config_.insert_mode == WorkspaceInsertMode::kRayCast;
  const int step = config_.insert_step_cells;
  std::size_t n = 0;
  scan_.clear();
  for (int r = 0; r < cloud.rows(); r += step) {
    const cv::Vec3f* p = cloud.row(r);
    for (int c = 0; c < cloud.cols() && n < keys_.size(); c += step) {
      if (!OrganizedCloud::isValid(p[c])) continue;
      const Eigen::Vector3f p_cam(p[c][0], p[c][1], p[c][2]);
      if (p_cam.squaredNorm() > range2) continue;
      const Eigen::Vector3f q = R * p_cam + t;
      if (rays) {
        scan_.push_back(q.x(), q.y(), q.z());
        ++n;
        continue;
      }
      octomap::OcTreeKey key;
      if (!tree_->coordToKeyChecked(octomap::point3d(q.x(), q.y(), q.z()), key)) continue;
      // Neighbouring pixels mostly fall in the same voxel: dropping a repeat of the previous key here
      // leaves the sort below a fraction of the points and the same set of voxels.
      const std::uint64_t packed = packKey(key);
      if (n == 0 || keys_[n - 1] != packed) keys_[n++] = packed;
    }
  }
  if (rays) {
    tree_->insertPointCloud(scan_, octomap::point3d(t.x(), t.y(), t.z()), -1.0, false, true);
    return true;
  }
  // One hit per voxel per frame: a voxel's log-odds then counts the frames that saw it.
  std::sort(keys_.begin(), keys_.begin() + n);
  const auto end = std::unique(keys_.begin(), keys_.begin() + n);
  for (auto it = keys_.begin(); it != end; ++it) tree_->updateNode(unpackKey(*it), true, true);
  // The leaves were updated without their parents (lazy_eval): an updateNode without it walks back up
  // the 16 levels after every voxel, taking the max of 8 children and trying to prune at each, which was
  // 3000 instructions per voxel. One pass over the tree afterwards gives the same tree: the parents the
  // max of their children, then every node whose 8 children are equal leaves pruned (the eager updates
  // leave no such node behind either, and a fully pruned tree of the same voxels is unique).
  tree_->updateInnerOccupancy();
  tree_->prune();
  return true;
}

// Occupied leaves, pruned ones expanded to resolution voxels.
bool WorkspaceMap::collectOccupied() {
  occupied_.clear();
  centres_xyz_.clear();
  const unsigned max_depth = tree_->getTreeDepth();
  const float res = static_cast<float>(tree_->getResolution());
  for (auto it = tree_->begin_leafs(), end = tree_->end_leafs(); it != end; ++it) {
    if (!tree_->isNodeOccupied(*it)) continue;
    const int span = 1 << (max_depth - it.getDepth());
    const octomap::OcTreeKey k0 = it.getIndexKey();
    if (occupied_.size() + static_cast<std::size_t>(span) * span * span >
        config_.max_occupied_voxels) {
      return false;
    }
    for (int dx = 0; dx < span; ++dx) {
      for (int dy = 0; dy < span; ++dy) {
        for (int dz = 0; dz < span; ++dz) {
          const VoxelIndex v{k0[0] + dx - kTreeMaxVal, k0[1] + dy - kTreeMaxVal,
                             k0[2] + dz - kTreeMaxVal};
          occupied_.push_back(v);
          const Eigen::Vector3f c = voxelCentre(v, res);
          centres_xyz_.insert(centres_xyz_.end(), {c.x(), c.y(), c.z()});
        }
      }
    }
  }
  return true;
}

bool WorkspaceMap::freeze() {
  if (!ready_) return false;
  unfreeze();
  if (!collectOccupied()) return false;
  frozen_ = true;
  if (!buildLookup(config_.lookup)) {
    unfreeze();
    return false;
  }
  return true;
}

bool WorkspaceMap::buildLookup(WorkspaceLookupKind kind) {
  if (!frozen_) return false;
  switch (kind) {
    case WorkspaceLookupKind::kOctree:
      octree_built_ = octree_lookup_.build(tree_.get(), config_.filter_distance_m);
      return octree_built_;
    case WorkspaceLookupKind::kKdTree:
      kdtree_built_ = kdtree_lookup_.build(centres_xyz_, config_.filter_distance_m);
      return kdtree_built_;
    case WorkspaceLookupKind::kGrid:
      grid_built_ = grid_.build(occupied_, tree_->getResolution(), config_.filter_distance_m,
                                config_.max_grid_cells);
      return grid_built_;
  }
  return false;
}

void WorkspaceMap::unfreeze() {
  frozen_ = false;
  octree_built_ = kdtree_built_ = grid_built_ = false;
}

bool WorkspaceMap::lookupBuilt(WorkspaceLookupKind kind) const {
  switch (kind) {
    case WorkspaceLookupKind::kOctree:
      return frozen_ && octree_built_;
    case WorkspaceLookupKind::kKdTree:
      return frozen_ && kdtree_built_;
    case WorkspaceLookupKind::kGrid:
      return frozen_ && grid_built_;
  }
  return false;
}

bool WorkspaceMap::isNear(const Eigen::Vector3f& p) const { return isNear(p, config_.lookup); }

bool WorkspaceMap::isNear(const Eigen::Vector3f& p, WorkspaceLookupKind kind) const {
  if (!lookupBuilt(kind)) return false;
  switch (kind) {
    case WorkspaceLookupKind::kOctree:
      return octree_lookup_.isNear(p);
    case WorkspaceLookupKind::kKdTree:
      return kdtree_lookup_.isNear(p);
    case WorkspaceLookupKind::kGrid:
      return grid_.isNear(p);
  }
  return false;
}

template <class Lookup>
int WorkspaceMap::filterWith(const Lookup& lookup, const Eigen::Isometry3d& T_odom_cam,
                             OrganizedCloud* cloud) const {
  const Eigen::Matrix3f R = T_odom_cam.linear().cast<float>();
  const Eigen::Vector3f t = T_odom_cam.translation().cast<float>();
  int removed = 0;
  for (int r = 0; r < cloud->rows(); ++r) {
    cv::Vec3f* p = cloud->row(r);
    for (int c = 0; c < cloud->cols(); ++c) {
      if (!OrganizedCloud::isValid(p[c])) continue;
      const Eigen::Vector3f q = R * Eigen::Vector3f(p[c][0], p[c][1], p[c][2]) + t;
      if (!lookup.isNear(q)) {
        OrganizedCloud::invalidate(p[c]);
        ++removed;
      }
    }
  }
  return removed;
}

int WorkspaceMap::filter(const Eigen::Isometry3d& T_odom_cam, OrganizedCloud* cloud) const {
  return filter(T_odom_cam, cloud, config_.lookup);
}

int WorkspaceMap::filter(const Eigen::Isometry3d& T_odom_cam, OrganizedCloud* cloud,
                         WorkspaceLookupKind kind) const {
  if (cloud == nullptr || !lookupBuilt(kind)) return -1;
  switch (kind) {
    case WorkspaceLookupKind::kOctree:
      return filterWith(octree_lookup_, T_odom_cam, cloud);
    case WorkspaceLookupKind::kKdTree:
      return filterWith(kdtree_lookup_, T_odom_cam, cloud);
    case WorkspaceLookupKind::kGrid:
      return filterWith(grid_, T_odom_cam, cloud);
  }
  return -1;
}

bool WorkspaceMap::write(std::ostream& out) const { return ready_ && tree_->writeBinaryConst(out); }

bool WorkspaceMap::read(std::istream& in) {
  if (!ready_) return false;
  unfreeze();
  if (!tree_->readBinary(in)) return false;
  config_.resolution_m = tree_->getResolution();
  configureTree();
  return true;
}

std::size_t WorkspaceMap::occupiedVoxelCount() const {
  if (!ready_) return 0;
  std::size_t count = 0;
  for (auto it = tree_->begin_leafs(), end = tree_->end_leafs(); it != end; ++it) {
    if (tree_->isNodeOccupied(*it)) {
      const std::size_t span = std::size_t{1} << (tree_->getTreeDepth() - it.getDepth());
      count += span * span * span;
    }
  }
  return count;
}

}  // namespace deepnav
