#pragma once
#include <cstdint>
#include <cstdlib>
#include <opencv2/core/hal/intrin.hpp>

namespace deepnav {

// Sum of absolute differences of two 16-byte descriptors: the l1 distance of ELAS's likelihood
// (p(o_r | o_l, d) ∝ exp(-beta |f_l - f_r|_1), Geiger et al. 2010). OpenCV's universal intrinsics:
// psadbw on x86-64, vabd + vaddlv on aarch64.
inline int sad16(const std::uint8_t* a, const std::uint8_t* b) {
#if CV_SIMD128
  return static_cast<int>(cv::v_reduce_sad(cv::v_load(a), cv::v_load(b)));
#else
  int sum = 0;
  for (int i = 0; i < 16; ++i) sum += std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i]));
  return sum;
#endif
}

}  // namespace deepnav
