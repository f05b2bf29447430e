#pragma once
#include <cmath>
#include <cstdint>
#include <cstring>

#include <Eigen/Core>

#if defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__SSE__)
#include <xmmintrin.h>
#elif defined(__aarch64__)
#include <arm_neon.h>
#endif

namespace deepnav::sim {

// Four floats in one register (SSE on x86-64, NEON on aarch64): GCC's generic vector extension, so the
// same source builds for both targets. Lane-wise + - * / round exactly as the scalar operations, so a
// loop rewritten on Float4 gives bit-identical results (no FMA contraction in the x86-64 baseline).
using Float4 = float __attribute__((vector_size(16)));
using Int4 = int __attribute__((vector_size(16)));

// Register to Eigen: one 16-byte copy, which the compiler keeps in the register once inlined.
inline Eigen::Vector4f toVector4f(Float4 v) {
  Eigen::Vector4f e;
  std::memcpy(e.data(), &v, sizeof(v));
  return e;
}

inline Float4 loadFloat4(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof(v));
  return v;
}

// Two adjacent 4-byte words (four 8-bit values each, e.g. B, G, R, 0) to two Float4s, exactly: one 8-byte
// load and integer unpacks (a scalar int-to-float conversion per byte would stall on its register).
inline void texelPairFloat4(const std::uint32_t* words, Float4* first, Float4* second) {
#if defined(__SSE2__)
  const __m128i zero = _mm_setzero_si128();
  const __m128i u16 = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(words)), zero);
  *first = reinterpret_cast<Float4>(_mm_cvtepi32_ps(_mm_unpacklo_epi16(u16, zero)));
  *second = reinterpret_cast<Float4>(_mm_cvtepi32_ps(_mm_unpackhi_epi16(u16, zero)));
#elif defined(__aarch64__)
  const uint16x8_t u16 = vmovl_u8(vld1_u8(reinterpret_cast<const std::uint8_t*>(words)));
  *first = reinterpret_cast<Float4>(vcvtq_f32_u32(vmovl_u16(vget_low_u16(u16))));
  *second = reinterpret_cast<Float4>(vcvtq_f32_u32(vmovl_u16(vget_high_u16(u16))));
#else
  const auto* b = reinterpret_cast<const std::uint8_t*>(words);
  *first = Float4{static_cast<float>(b[0]), static_cast<float>(b[1]), static_cast<float>(b[2]), static_cast<float>(b[3])};
  *second = Float4{static_cast<float>(b[4]), static_cast<float>(b[5]), static_cast<float>(b[6]), static_cast<float>(b[7])};
#endif
}

// Correctly rounded square root per lane (as std::sqrt), in one instruction where there is one.
inline Float4 sqrt4(Float4 x) {
#if defined(__SSE__)
  return reinterpret_cast<Float4>(_mm_sqrt_ps(reinterpret_cast<__m128>(x)));
#elif defined(__aarch64__)
  return reinterpret_cast<Float4>(vsqrtq_f32(reinterpret_cast<float32x4_t>(x)));
#else
  return Float4{std::sqrt(x[0]), std::sqrt(x[1]), std::sqrt(x[2]), std::sqrt(x[3])};
#endif
}

}  // namespace deepnav::sim
