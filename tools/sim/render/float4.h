#pragma once
#include <cmath>
#include <cstring>

#include <Eigen/Core>

#if defined(__SSE__)
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
