#pragma once
#include <cstdint>
#include <cstdlib>

#if defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__ARM_NEON) && defined(__aarch64__)
#include <arm_neon.h>
#endif

namespace deepnav {

// Sum of absolute differences of two 16-byte descriptors: the l1 distance of ELAS's likelihood
// (p(o_r | o_l, d) ∝ exp(-beta |f_l - f_r|_1), Geiger et al. 2010). One psadbw on x86-64, one vabd
// + vaddlv on aarch64.
inline int sad16(const std::uint8_t* a, const std::uint8_t* b) {
#if defined(__SSE2__)
  const __m128i sum = _mm_sad_epu8(_mm_loadu_si128(reinterpret_cast<const __m128i*>(a)),
                                   _mm_loadu_si128(reinterpret_cast<const __m128i*>(b)));
  return _mm_cvtsi128_si32(sum) + _mm_extract_epi16(sum, 4);
#elif defined(__ARM_NEON) && defined(__aarch64__)
  return static_cast<int>(vaddlvq_u8(vabdq_u8(vld1q_u8(a), vld1q_u8(b))));
#else
  int sum = 0;
  for (int i = 0; i < 16; ++i) sum += std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i]));
  return sum;
#endif
}

}  // namespace deepnav
