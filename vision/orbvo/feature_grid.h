#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include "vision/orbvo/orb_feature.h"

namespace deepnav {

// Spatial index of one image's features on square cells, for searches in a window around a
// predicted pixel. A counting sort per build(); sized in init(), does not allocate afterwards.
class FeatureGrid {
 public:
  bool init(int width_px, int height_px, int cell_px, int max_features) {
    if (width_px < 1 || height_px < 1 || cell_px < 1 || max_features < 1) return false;
    cell_px_ = cell_px;
    cols_ = (width_px + cell_px - 1) / cell_px;
    rows_ = (height_px + cell_px - 1) / cell_px;
    cell_start_.assign(static_cast<std::size_t>(cols_) * rows_ + 1, 0);
    sorted_.assign(max_features, 0);
    return true;
  }

  void build(const std::vector<OrbFeature>& features) {
    std::fill(cell_start_.begin(), cell_start_.end(), 0);
    const int n = std::min(static_cast<int>(features.size()), static_cast<int>(sorted_.size()));
    for (int i = 0; i < n; ++i) ++cell_start_[cellOf(features[i]) + 1];
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    for (int i = 0; i < n; ++i) sorted_[cell_start_[cellOf(features[i])]++] = i;
    for (std::size_t c = cell_start_.size() - 1; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
    cell_start_[0] = 0;
  }

  // Calls visit(index) for every feature in the cells overlapping the square of half side
  // radius_px.
  template <class Visit>
  void forEachNear(double u_px, double v_px, double radius_px, Visit&& visit) const {
    const int c0 = std::max(0, static_cast<int>(std::floor((u_px - radius_px) / cell_px_)));
    const int c1 = std::min(cols_ - 1, static_cast<int>(std::floor((u_px + radius_px) / cell_px_)));
    const int r0 = std::max(0, static_cast<int>(std::floor((v_px - radius_px) / cell_px_)));
    const int r1 = std::min(rows_ - 1, static_cast<int>(std::floor((v_px + radius_px) / cell_px_)));
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        const int cell = r * cols_ + c;
        for (int k = cell_start_[cell]; k < cell_start_[cell + 1]; ++k) visit(sorted_[k]);
      }
    }
  }

 private:
  int cellOf(const OrbFeature& f) const {
    const int c = std::clamp(static_cast<int>(f.u_px) / cell_px_, 0, cols_ - 1);
    const int r = std::clamp(static_cast<int>(f.v_px) / cell_px_, 0, rows_ - 1);
    return r * cols_ + c;
  }

  int cell_px_ = 16;
  int cols_ = 0;
  int rows_ = 0;
  std::vector<int> cell_start_;
  std::vector<int> sorted_;
};

}  // namespace deepnav
