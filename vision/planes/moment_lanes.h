#pragma once
#include <opencv2/core/hal/intrin.hpp>

#include "vision/planes/tile_sums.h"

namespace deepnav {

// Ten running moment sums (count, first and second moments of q = p - ref) in four float lanes;
// masked lanes add zero. The tile sums (tile_sums.cpp) and the fit's tile-by-tile feed (plane_fit.cpp)
// accumulate with it.
struct MomentLanes {
  cv::v_float32x4 n = cv::v_setzero_f32(), x = cv::v_setzero_f32(), y = cv::v_setzero_f32(),
                  z = cv::v_setzero_f32(), xx = cv::v_setzero_f32(), xy = cv::v_setzero_f32(),
                  xz = cv::v_setzero_f32(), yy = cv::v_setzero_f32(), yz = cv::v_setzero_f32(),
                  zz = cv::v_setzero_f32();
  void add(const cv::v_float32x4& mask, cv::v_float32x4 qx, cv::v_float32x4 qy,
           cv::v_float32x4 qz) {
    const cv::v_float32x4 zero = cv::v_setzero_f32();
    n = n + cv::v_select(mask, cv::v_setall_f32(1.0f), zero);
    qx = cv::v_select(mask, qx, zero);
    qy = cv::v_select(mask, qy, zero);
    qz = cv::v_select(mask, qz, zero);
    x = x + qx;
    y = y + qy;
    z = z + qz;
    xx = cv::v_fma(qx, qx, xx);
    xy = cv::v_fma(qx, qy, xy);
    xz = cv::v_fma(qx, qz, xz);
    yy = cv::v_fma(qy, qy, yy);
    yz = cv::v_fma(qy, qz, yz);
    zz = cv::v_fma(qz, qz, zz);
  }
  TileSums reduce() const {
    return TileSums{cv::v_reduce_sum(n),  cv::v_reduce_sum(x),  cv::v_reduce_sum(y),
                    cv::v_reduce_sum(z),  cv::v_reduce_sum(xx), cv::v_reduce_sum(xy),
                    cv::v_reduce_sum(xz), cv::v_reduce_sum(yy), cv::v_reduce_sum(yz),
                    cv::v_reduce_sum(zz)};
  }
};

}  // namespace deepnav
