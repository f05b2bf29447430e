#pragma once
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <nanoflann.hpp>
#include <vector>

namespace deepnav {

// "Is there an occupied voxel centre within distance of p?" answered by a nanoflann kd-tree over
// the occupied voxel centres, built once when the map is frozen. The query stops at the first
// centre inside the radius (a result set that asks nanoflann to stop), so points near the map are
// cheap; points far from it descend until every cell within the radius is ruled out.
class KdTreeLookup {
 public:
  KdTreeLookup();
  ~KdTreeLookup();
  KdTreeLookup(const KdTreeLookup&) = delete;
  KdTreeLookup& operator=(const KdTreeLookup&) = delete;

  // centres_xyz: 3 floats per occupied voxel centre (copied).
  bool build(const std::vector<float>& centres_xyz, double distance_m);
  bool isNear(const Eigen::Vector3f& p) const;
  std::size_t size() const { return points_.size() / 3; }

  // nanoflann dataset adaptor
  std::size_t kdtree_get_point_count() const { return points_.size() / 3; }
  float kdtree_get_pt(std::uint32_t i, std::size_t dim) const { return points_[3 * i + dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box& /*bb*/) const {
    return false;
  }

 private:
  using Index =
      nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, KdTreeLookup>,
                                          KdTreeLookup, 3, std::uint32_t>;
  std::vector<float> points_;
  std::unique_ptr<Index> index_;
  float distance2_ = 0.0f;
};

}  // namespace deepnav
