#pragma once
#include "tools/sim/render/float4.h"

namespace deepnav::sim {

// exp(x) per lane, relative error below 2e-7 for x in [-87, 88] (clamped outside): x = n ln2 + r with
// |r| <= ln2 / 2 (Cody-Waite, ln2 in two parts), exp(r) by its Taylor polynomial to degree 6, 2^n put
// into the exponent bits. The water terms need thousands of these per frame (exp per lane of std::exp
// is ten times slower).
inline Float4 exp4(Float4 x) {
  const Float4 lo = Float4{} - 87.0f, hi = Float4{} + 88.0f;
  x = x < lo ? lo : x;
  x = x > hi ? hi : x;
  const Float4 n_real = x * 1.44269504f + 0.5f;
  Int4 n = __builtin_convertvector(n_real, Int4);
  n -= reinterpret_cast<Int4>(__builtin_convertvector(n, Float4) > n_real) & 1;  // floor
  const Float4 nf = __builtin_convertvector(n, Float4);
  const Float4 r = (x - nf * 0.693359375f) + nf * 2.12194440e-4f;
  Float4 p = Float4{} + 1.0f / 720.0f;
  p = p * r + 1.0f / 120.0f;
  p = p * r + 1.0f / 24.0f;
  p = p * r + 1.0f / 6.0f;
  p = p * r + 0.5f;
  p = p * r + 1.0f;
  p = p * r + 1.0f;
  return p * reinterpret_cast<Float4>((n + 127) << 23);
}

}  // namespace deepnav::sim
