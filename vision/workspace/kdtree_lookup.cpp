#include "vision/workspace/kdtree_lookup.h"

namespace deepnav {
namespace {

// Stops the search at the first point within the radius.
class AnyWithinRadius {
 public:
  explicit AnyWithinRadius(float radius2) : radius2_(radius2) {}
  bool full() const { return true; }
  float worstDist() const { return radius2_; }
  bool addPoint(float dist2, std::uint32_t /*index*/) {
    if (dist2 <= radius2_) found_ = true;
    return !found_;
  }
  bool found() const { return found_; }

 private:
  float radius2_;
  bool found_ = false;
};

}  // namespace

KdTreeLookup::KdTreeLookup() = default;
KdTreeLookup::~KdTreeLookup() = default;

bool KdTreeLookup::build(const std::vector<float>& centres_xyz, double distance_m) {
  if (centres_xyz.size() % 3 != 0 || distance_m < 0.0) return false;
  points_ = centres_xyz;
  // Radius inflated by one float ulp-scale margin: nanoflann admits dist < worstDist only.
  distance2_ = static_cast<float>(distance_m * distance_m) * (1.0f + 1e-6f);
  index_ = std::make_unique<Index>(3, *this, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  index_->buildIndex();
  return true;
}

bool KdTreeLookup::isNear(const Eigen::Vector3f& p) const {
  if (!index_ || points_.empty()) return false;
  AnyWithinRadius result(distance2_);
  const float query[3] = {p.x(), p.y(), p.z()};
  index_->findNeighbors(result, query, nanoflann::SearchParams());
  return result.found();
}

}  // namespace deepnav
