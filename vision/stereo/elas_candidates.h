#pragma once
#include <cstdint>
#include <vector>

#include "vision/stereo/elas_support.h"

namespace deepnav {

// Disparity candidates from nearby support points (Geiger et al. 2010, the "d in N_S"
// part of the prior): the image is cut into cells of grid_size_px; a cell's candidates are the
// support disparities, +-1, of every support point in the cell and its eight neighbours. They let
// the dense matcher jump to a surface the piecewise-planar mean misses (depth edges, thin objects).
// Stored as bit masks of kWords 64-bit words (bit d = candidate d).
class ElasCandidates {
 public:
  static constexpr int kWords = 4;  // up to 256 disparities

  bool allocate(int width_px, int height_px, int grid_size_px, int num_disparities);
  void build(const std::vector<SupportPoint>& points, bool view_right);

  const std::uint64_t* cellMask(int u_px, int v_px) const {
    const int cell = (v_px / grid_size_px_) * cols_ + u_px / grid_size_px_;
    return merged_.data() + static_cast<std::size_t>(cell) * kWords;
  }
  int words() const { return words_; }
  int gridSize() const { return grid_size_px_; }

 private:
  int grid_size_px_ = 1;
  int cols_ = 0;
  int rows_ = 0;
  int num_disparities_ = 0;
  int words_ = 1;
  std::vector<std::uint64_t> own_;     // per cell: disparities of its own support points
  std::vector<std::uint64_t> merged_;  // per cell: union over the 3x3 neighbourhood
};

}  // namespace deepnav
