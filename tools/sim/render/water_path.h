#pragma once
#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "tools/sim/render/float4.h"
#include "tools/sim/render/water_optics.h"

namespace deepnav::sim {

// Transmittance of a water path, exp(-beta_c x) per channel, from a table (1 cm steps, linear
// interpolation, relative error < 1e-5 for beta <= 2 /m): the shading needs three of them per pixel.
// Channels B, G, R in lanes 0-2 of a 4-float vector (lane 3 is 1), so that one SSE operation
// interpolates all three.
class WaterPath {
 public:
  void init(const WaterOptics& optics, float max_length_m) {
    const int n = static_cast<int>(max_length_m / kStep_m) + 2;
    table_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      for (int c = 0; c < 3; ++c) table_[i][c] = std::exp(-optics.attenuation_per_m[c] * (i * kStep_m));
      table_[i][3] = 1.0f;
    }
    last_ = static_cast<float>(n - 2);
  }
  // In two steps, for four path lengths in the lanes (the shading's packets): where each falls in the
  // table, lane-wise (clamped to [0, the table's end]), then each lane's interpolation.
  struct Place4 {
    Int4 row;
    Float4 fraction;
  };
  Place4 locate4(Float4 x_m) const {
    const Float4 clamped_low = x_m < 0.0f ? Float4{} : x_m;  // std::max(x, 0)
    const Float4 scaled = clamped_low * (1.0f / kStep_m);
    const Float4 f = last_ < scaled ? Float4{} + last_ : scaled;  // std::min(f, last)
    const Int4 row = __builtin_convertvector(f, Int4);
    return {row, f - __builtin_convertvector(row, Float4)};
  }
  Eigen::Vector4f interpolate(int row, float fraction) const {
    return table_[row] + fraction * (table_[row + 1] - table_[row]);
  }

 private:
  static constexpr float kStep_m = 0.01f;
  std::vector<Eigen::Vector4f> table_;
  float last_ = 0.0f;
};

}  // namespace deepnav::sim
