#include "vision/stereo/elas_candidates.h"

#include <algorithm>

namespace deepnav {

bool ElasCandidates::allocate(int width_px, int height_px, int grid_size_px, int num_disparities) {
  if (grid_size_px < 1 || num_disparities < 1 || num_disparities > 64 * kWords) return false;
  grid_size_px_ = grid_size_px;
  cols_ = (width_px + grid_size_px - 1) / grid_size_px;
  rows_ = (height_px + grid_size_px - 1) / grid_size_px;
  num_disparities_ = num_disparities;
  words_ = (num_disparities + 63) / 64;
  const std::size_t size = static_cast<std::size_t>(cols_) * rows_ * kWords;
  own_.assign(size, 0);
  merged_.assign(size, 0);
  return true;
}

void ElasCandidates::build(const std::vector<SupportPoint>& points, bool view_right) {
  std::fill(own_.begin(), own_.end(), 0);
  std::fill(merged_.begin(), merged_.end(), 0);
  for (const SupportPoint& p : points) {
    const int u = view_right ? p.u_px - p.d_px : p.u_px;
    if (u < 0) continue;
    std::uint64_t* mask =
        own_.data() +
        static_cast<std::size_t>((p.v_px / grid_size_px_) * cols_ + u / grid_size_px_) * kWords;
    for (int d = std::max(0, p.d_px - 1); d <= std::min(num_disparities_ - 1, p.d_px + 1); ++d) {
      mask[d >> 6] |= std::uint64_t{1} << (d & 63);
    }
  }
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) {
      std::uint64_t* out = merged_.data() + static_cast<std::size_t>(r * cols_ + c) * kWords;
      for (int r2 = std::max(0, r - 1); r2 <= std::min(rows_ - 1, r + 1); ++r2) {
        for (int c2 = std::max(0, c - 1); c2 <= std::min(cols_ - 1, c + 1); ++c2) {
          const std::uint64_t* in =
              own_.data() + static_cast<std::size_t>(r2 * cols_ + c2) * kWords;
          for (int w = 0; w < kWords; ++w) out[w] |= in[w];
        }
      }
    }
  }
}

}  // namespace deepnav
