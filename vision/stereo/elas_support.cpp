#include "vision/stereo/elas_support.h"

#include <algorithm>
#include <climits>
#include <cstdlib>

#include "vision/stereo/sad16.h"

namespace deepnav {
namespace {

struct BestTwo {
  int best_d = -1;
  int best_cost = INT_MAX;
  int second_cost = INT_MAX;  // best cost at |d - best_d| > 1
};

// Scans a full cost curve (at most 256 disparities). The second best excludes the best's
// immediate neighbours, whose cost is close to the best on any smooth surface and says nothing
// about ambiguity.
template <typename CostFn>
BestTwo scanCosts(int d_count, CostFn cost) {
  int costs[256];
  BestTwo r;
  for (int d = 0; d < d_count; ++d) {
    costs[d] = cost(d);
    if (costs[d] < r.best_cost) {
      r.best_cost = costs[d];
      r.best_d = d;
    }
  }
  for (int d = 0; d < d_count; ++d) {
    if (std::abs(d - r.best_d) > 1) r.second_cost = std::min(r.second_cost, costs[d]);
  }
  return r;
}

bool isUnique(const BestTwo& r, float ratio) {
  if (r.best_d < 0 || r.second_cost == INT_MAX) return false;
  return static_cast<float>(r.best_cost) < ratio * static_cast<float>(r.second_cost);
}

}  // namespace

bool ElasSupport::allocate(const ElasParams& params, int width_px, int height_px) {
  if (params.support_step_px < 1 || params.num_disparities < 2) return false;
  params_ = params;
  width_px_ = width_px;
  height_px_ = height_px;
  grid_cols_ = (width_px - 1) / params.support_step_px + 1;
  grid_rows_ = (height_px - 1) / params.support_step_px + 1;
  const std::size_t nodes = static_cast<std::size_t>(grid_cols_) * grid_rows_;
  grid_d_.assign(nodes, -1);
  filtered_d_.assign(nodes, -1);
  points_.reserve(nodes);
  mesh_points_.reserve(nodes);
  return true;
}

void ElasSupport::compute(const ElasDescriptorImage& left, const ElasDescriptorImage& right) {
  const int step = params_.support_step_px;
  for (int gv = 0; gv < grid_rows_; ++gv) {
    for (int gu = 0; gu < grid_cols_; ++gu) {
      grid_d_[cell(gu, gv)] =
          static_cast<std::int16_t>(matchGridPoint(left, right, gu * step, gv * step));
    }
  }
  removeInconsistent();
  collectPoints();
}

// Full-range match left -> right, then right -> left from the matched pixel.
int ElasSupport::matchGridPoint(const ElasDescriptorImage& left, const ElasDescriptorImage& right,
                                int u, int v) const {
  const std::uint8_t* dl = left.at(u, v);
  if (descriptorTexture(dl) < params_.support_texture) return -1;
  const int d_count_l = std::min(params_.num_disparities, u + 1);
  const BestTwo lr = scanCosts(d_count_l, [&](int d) { return sad16(dl, right.at(u - d, v)); });
  if (!isUnique(lr, params_.support_ratio)) return -1;
  const int ur = u - lr.best_d;
  const std::uint8_t* dr = right.at(ur, v);
  const int d_count_r = std::min(params_.num_disparities, width_px_ - ur);
  const BestTwo rl = scanCosts(d_count_r, [&](int d) { return sad16(dr, left.at(ur + d, v)); });
  if (!isUnique(rl, params_.support_ratio)) return -1;
  if (std::abs(rl.best_d - lr.best_d) > params_.support_lr_threshold_px) return -1;
  return lr.best_d;
}

void ElasSupport::removeInconsistent() {
  const int win = params_.incon_window_cells;
  for (int gv = 0; gv < grid_rows_; ++gv) {
    for (int gu = 0; gu < grid_cols_; ++gu) {
      const int d = grid_d_[cell(gu, gv)];
      filtered_d_[cell(gu, gv)] = -1;
      if (d < 0) continue;
      int agreeing = 0;
      for (int v2 = std::max(0, gv - win); v2 <= std::min(grid_rows_ - 1, gv + win); ++v2) {
        for (int u2 = std::max(0, gu - win); u2 <= std::min(grid_cols_ - 1, gu + win); ++u2) {
          const int d2 = grid_d_[cell(u2, v2)];
          if (d2 >= 0 && std::abs(d2 - d) <= params_.incon_threshold_px) ++agreeing;
        }
      }
      // the count includes the point itself
      if (agreeing - 1 >= params_.incon_min_support)
        filtered_d_[cell(gu, gv)] = grid_d_[cell(gu, gv)];
    }
  }
}

bool ElasSupport::isRedundant(int gu, int gv) const {
  const int d = filtered_d_[cell(gu, gv)];
  const int dirs[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
  for (const auto& dir : dirs) {
    bool similar = false;
    for (int k = 1; k <= params_.redundant_window_cells; ++k) {
      const int u2 = gu + k * dir[0];
      const int v2 = gv + k * dir[1];
      if (u2 < 0 || v2 < 0 || u2 >= grid_cols_ || v2 >= grid_rows_) break;
      const int d2 = filtered_d_[cell(u2, v2)];
      if (d2 < 0) continue;
      similar = std::abs(d2 - d) <= params_.redundant_threshold_px;
      break;
    }
    if (!similar) return false;
  }
  return true;
}

void ElasSupport::collectPoints() {
  points_.clear();
  mesh_points_.clear();
  const int step = params_.support_step_px;
  for (int gv = 0; gv < grid_rows_; ++gv) {
    for (int gu = 0; gu < grid_cols_; ++gu) {
      const int d = filtered_d_[cell(gu, gv)];
      if (d < 0) continue;
      const SupportPoint p{gu * step, gv * step, d};
      points_.push_back(p);
      if (!isRedundant(gu, gv)) mesh_points_.push_back(p);
    }
  }
}

}  // namespace deepnav
