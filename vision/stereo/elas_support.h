#pragma once
#include <cstdint>
#include <vector>

#include "vision/stereo/elas_descriptor.h"
#include "vision/stereo/elas_params.h"

namespace deepnav {

// A robust sparse match: left pixel (u_px, v_px) has disparity d_px.
struct SupportPoint {
  int u_px = 0;
  int v_px = 0;
  int d_px = 0;
};

// Support points of ELAS (Geiger et al. 2010): descriptors matched over the full
// disparity range on a regular grid, kept only when the match is unique (best < ratio * second
// best, away from the best's own neighbours) and left-right consistent; then isolated points,
// whose disparity few neighbours share, are removed.
class ElasSupport {
 public:
  bool allocate(const ElasParams& params, int width_px, int height_px);
  void compute(const ElasDescriptorImage& left, const ElasDescriptorImage& right);

  // All consistent support points (the candidate sets of the prior use these).
  const std::vector<SupportPoint>& points() const { return points_; }
  // The subset worth triangulating: redundant points in planar runs left out.
  const std::vector<SupportPoint>& meshPoints() const { return mesh_points_; }

 private:
  int matchGridPoint(const ElasDescriptorImage& left, const ElasDescriptorImage& right, int u,
                     int v) const;
  void removeInconsistent();
  bool isRedundant(int gu, int gv) const;
  void collectPoints();
  int cell(int gu, int gv) const { return gv * grid_cols_ + gu; }

  ElasParams params_;
  int width_px_ = 0;
  int height_px_ = 0;
  int grid_cols_ = 0;
  int grid_rows_ = 0;
  std::vector<std::int16_t> grid_d_;      // disparity per grid node, -1 = none
  std::vector<std::int16_t> filtered_d_;  // after removing inconsistent nodes
  std::vector<SupportPoint> points_;
  std::vector<SupportPoint> mesh_points_;
};

}  // namespace deepnav
