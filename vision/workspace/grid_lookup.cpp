#include "vision/workspace/grid_lookup.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace deepnav {

bool GridLookup::build(const std::vector<VoxelIndex>& occupied, double resolution_m,
                       double distance_m, std::size_t max_cells) {
  bits_.clear();
  nx_ = ny_ = nz_ = 0;
  if (resolution_m <= 0.0 || distance_m < 0.0) return false;
  inv_res_ = static_cast<float>(1.0 / resolution_m);
  if (occupied.empty()) return true;
  // Ball of voxel offsets whose centres are within distance + half a diagonal.
  const double reach = distance_m / resolution_m + std::sqrt(3.0) / 2.0;
  const int n = static_cast<int>(std::floor(reach));
  std::vector<std::array<int, 3>> ball;
  for (int x = -n; x <= n; ++x) {
    for (int y = -n; y <= n; ++y) {
      for (int z = -n; z <= n; ++z) {
        if (x * x + y * y + z * z <= reach * reach) ball.push_back({x, y, z});
      }
    }
  }
  VoxelIndex lo = occupied.front(), hi = occupied.front();
  for (const VoxelIndex& v : occupied) {
    lo = VoxelIndex{std::min(lo.x, v.x), std::min(lo.y, v.y), std::min(lo.z, v.z)};
    hi = VoxelIndex{std::max(hi.x, v.x), std::max(hi.y, v.y), std::max(hi.z, v.z)};
  }
  min_ = VoxelIndex{lo.x - n, lo.y - n, lo.z - n};
  nx_ = static_cast<std::int64_t>(hi.x) - lo.x + 1 + 2 * n;
  ny_ = static_cast<std::int64_t>(hi.y) - lo.y + 1 + 2 * n;
  nz_ = static_cast<std::int64_t>(hi.z) - lo.z + 1 + 2 * n;
  if (static_cast<double>(nx_) * ny_ * nz_ > static_cast<double>(max_cells)) {
    nx_ = ny_ = nz_ = 0;
    return false;
  }
  bits_.assign((cellCount() + 63) / 64, 0u);
  for (const VoxelIndex& v : occupied) {
    for (const auto& o : ball) {
      const std::int64_t x = v.x + o[0] - min_.x, y = v.y + o[1] - min_.y, z = v.z + o[2] - min_.z;
      const std::size_t i = static_cast<std::size_t>((z * ny_ + y) * nx_ + x);
      bits_[i >> 6] |= std::uint64_t{1} << (i & 63);
    }
  }
  return true;
}

}  // namespace deepnav
