#include "vision/orbvo/fixed_point_gaussian.h"

#include <algorithm>
#include <utility>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/imgproc.hpp>

namespace deepnav {
namespace {

constexpr int kWeightSum = 256;  // OpenCV's 8-bit Gaussian weights are fixed point with 8 fraction bits

// BORDER_REFLECT_101 (gfedcb|abcdefgh|gfedcba) for |overshoot| < n.
int reflect101(int i, int n) {
  if (i < 0) return -i;
  if (i >= n) return 2 * n - 2 - i;
  return i;
}

using Weights = std::array<std::uint16_t, FixedPointGaussian::kMaxRadiusPx + 1>;

// Where the row pass multiplies pairs of signed 16-bit lanes into 32 bits (SSE2's pmaddwd, below), the
// column sums are stored minus 2^15 (V ^ 0x8000 read as int16); elsewhere as they are.
#if CV_SIMD128 && !CV_NEON
constexpr std::uint16_t kSumBias = 0x8000;
#else
constexpr std::uint16_t kSumBias = 0;
#endif

#if CV_SIMD128
// The sum of two 16-bit lanes that cannot overflow. NEON fuses a wrapping add with the widening before it
// and the multiply after it (uaddl, mla: the aarch64 column loop 49 instead of 85 instructions per 16
// pixels), where the saturating add of the universal intrinsics stays a separate instruction; on SSE2 the
// saturating add compiles to the shorter loop (callgrind: 5.7 M against 7.2 M per extraction).
inline cv::v_uint16x8 addNoOverflow(const cv::v_uint16x8& a, const cv::v_uint16x8& b) {
#if CV_NEON
  return cv::v_add_wrap(a, b);
#else
  return a + b;
#endif
}
#endif

// V(x) = w_0 I(y, x) + sum_k w_k (I(y-k, x) + I(y+k, x)), exact in 16 bits (at most 255 * 256). The
// radius is a template argument so that the tap loops unroll.
template <int R>
void columnSums(const Weights& w, const cv::Mat& src, int y, std::uint16_t* sums) {
  std::array<const std::uint8_t*, 2 * R + 1> row{};  // row[R + i]: source row y + i
  for (int i = -R; i <= R; ++i) row[R + i] = src.ptr<std::uint8_t>(reflect101(y + i, src.rows));
  int x = 0;
#if CV_SIMD128
  std::array<cv::v_uint16x8, R + 1> wv;
  for (int k = 0; k <= R; ++k) wv[k] = cv::v_setall_u16(w[k]);
  for (; x <= src.cols - 16; x += 16) {
    cv::v_uint16x8 lo, hi;
    cv::v_expand(cv::v_load(row[R] + x), lo, hi);
    cv::v_uint16x8 sum_lo = cv::v_mul_wrap(lo, wv[0]);
    cv::v_uint16x8 sum_hi = cv::v_mul_wrap(hi, wv[0]);
#pragma GCC unroll 16
    for (int k = 1; k <= R; ++k) {
      cv::v_uint16x8 a_lo, a_hi, b_lo, b_hi;
      cv::v_expand(cv::v_load(row[R - k] + x), a_lo, a_hi);
      cv::v_expand(cv::v_load(row[R + k] + x), b_lo, b_hi);
      sum_lo = addNoOverflow(sum_lo, cv::v_mul_wrap(addNoOverflow(a_lo, b_lo), wv[k]));
      sum_hi = addNoOverflow(sum_hi, cv::v_mul_wrap(addNoOverflow(a_hi, b_hi), wv[k]));
    }
    if constexpr (kSumBias != 0) {
      const cv::v_uint16x8 bias = cv::v_setall_u16(kSumBias);
      sum_lo = sum_lo ^ bias;
      sum_hi = sum_hi ^ bias;
    }
    cv::v_store(sums + x, sum_lo);
    cv::v_store(sums + x + 8, sum_hi);
  }
#endif
  for (; x < src.cols; ++x) {
    unsigned sum = w[0] * row[R][x];
    for (int k = 1; k <= R; ++k) sum += w[k] * (row[R - k][x] + row[R + k][x]);
    sums[x] = static_cast<std::uint16_t>(sum ^ kSumBias);
  }
}

template <int R>
void reflectEnds(std::uint16_t* sums, int width_px) {
  for (int k = 1; k <= R; ++k) {
    sums[-k] = sums[k];
    sums[width_px - 1 + k] = sums[width_px - 1 - k];
  }
}

// out = (sum_k w_k V(x+k) + 2^15) >> 16 for 8 pixels from p, two formulations of the same integers.
// NEON multiplies 16-bit lanes into 32-bit accumulators in one instruction (umlal), so there each tap is
// one widening multiply-add per half. SSE2 has no such instruction, but it multiplies pairs of signed
// 16-bit lanes and adds each pair into a 32-bit lane (pmaddwd, v_dotprod): with U = V - 2^15 (the
// biased column sums) and the lanes of x-k and x+k interleaved, one instruction gives w_k (U(x-k) +
// U(x+k)) for 4 pixels. Since the weights sum to 256, sum_k w_k V = sum_k w_k U + 2^23, so
//   out = (sum_k w_k U + 2^23 + 2^15) >> 16,
// every sum within [-2^23, 2^23] (the split into 256 hi + lo that this replaced took 12 instructions per
// tap and 8 pixels; this takes 8).
#if CV_SIMD128
#if CV_NEON
using RowWeight = cv::v_uint16x8;
inline RowWeight rowWeight(std::uint16_t w) { return cv::v_setall_u16(w); }

template <int R>
[[gnu::always_inline]] inline cv::v_uint16x8 blur8(const std::array<RowWeight, R + 1>& wv,
                                                    const std::uint16_t* p) {
  cv::v_uint32x4 lo, hi;
  cv::v_mul_expand(cv::v_load(p), wv[0], lo, hi);
#pragma GCC unroll 16
  for (int k = 1; k <= R; ++k) {
    cv::v_uint32x4 l0, l1, r0, r1;
    cv::v_mul_expand(cv::v_load(p - k), wv[k], l0, l1);
    cv::v_mul_expand(cv::v_load(p + k), wv[k], r0, r1);
    lo += l0 + r0;
    hi += l1 + r1;
  }
  const cv::v_uint32x4 half = cv::v_setall_u32(1u << 15);
  return cv::v_pack(cv::v_shr<16>(lo + half), cv::v_shr<16>(hi + half));
}
#else
using RowWeight = cv::v_int16x8;
inline RowWeight rowWeight(std::uint16_t w) { return cv::v_setall_s16(static_cast<std::int16_t>(w)); }

template <int R>
[[gnu::always_inline]] inline cv::v_uint16x8 blur8(const std::array<RowWeight, R + 1>& wv,
                                                    const std::uint16_t* p) {
  const auto load = [](const std::uint16_t* q) { return cv::v_reinterpret_as_s16(cv::v_load(q)); };
  cv::v_int16x8 pairs_lo, pairs_hi;
  cv::v_zip(load(p), cv::v_setzero_s16(), pairs_lo, pairs_hi);  // the centre, paired with a 0
  cv::v_int32x4 lo = cv::v_dotprod(pairs_lo, wv[0]);
  cv::v_int32x4 hi = cv::v_dotprod(pairs_hi, wv[0]);
#pragma GCC unroll 16
  for (int k = 1; k <= R; ++k) {
    cv::v_zip(load(p - k), load(p + k), pairs_lo, pairs_hi);
    lo += cv::v_dotprod(pairs_lo, wv[k]);
    hi += cv::v_dotprod(pairs_hi, wv[k]);
  }
  const cv::v_int32x4 offset = cv::v_setall_s32((1 << 23) + (1 << 15));
  return cv::v_reinterpret_as_u16(cv::v_pack(cv::v_shr<16>(lo + offset), cv::v_shr<16>(hi + offset)));
}
#endif
#endif

template <int R>
void rowPass(const Weights& w, const std::uint16_t* sums, int width_px, std::uint8_t* out) {
  int x = 0;
#if CV_SIMD128
  std::array<RowWeight, R + 1> wv;
  for (int k = 0; k <= R; ++k) wv[k] = rowWeight(w[k]);
  for (; x <= width_px - 16; x += 16) {
    cv::v_store(out + x, cv::v_pack(blur8<R>(wv, sums + x), blur8<R>(wv, sums + x + 8)));
  }
#endif
  const auto V = [&](int i) -> std::uint32_t { return sums[i] ^ kSumBias; };
  for (; x < width_px; ++x) {
    std::uint32_t sum = w[0] * V(x);
    for (int k = 1; k <= R; ++k) sum += w[k] * (V(x - k) + V(x + k));
    out[x] = static_cast<std::uint8_t>((sum + (1u << 15)) >> 16);
  }
}

// `sums` has R writable entries before it and after its src.cols.
template <int R>
void blurImage(const Weights& w, const cv::Mat& src, cv::Mat* dst, std::uint16_t* sums) {
  for (int y = 0; y < src.rows; ++y) {
    columnSums<R>(w, src, y, sums);
    reflectEnds<R>(sums, src.cols);
    rowPass<R>(w, sums, src.cols, dst->ptr<std::uint8_t>(y));
  }
}

using BlurFn = void (*)(const Weights&, const cv::Mat&, cv::Mat*, std::uint16_t*);

template <std::size_t... I>
constexpr std::array<BlurFn, sizeof...(I)> blurTable(std::index_sequence<I...>) {
  return {&blurImage<static_cast<int>(I)>...};
}

// Index 0 is never called (init() refuses a kernel of one tap).
constexpr auto kBlurByRadius = blurTable(std::make_index_sequence<FixedPointGaussian::kMaxRadiusPx + 1>());

}  // namespace

bool FixedPointGaussian::init(double sigma_px, int kernel_px, const std::vector<cv::Size>& sizes) {
  radius_px_ = 0;
  sigma_px_ = sigma_px;
  kernel_ = cv::Size(kernel_px, kernel_px);
  const bool kernel_ok = kernel_px == 0 || (kernel_px % 2 == 1 && kernel_px >= 3);
  if (!(sigma_px > 0.0) || !kernel_ok || !readWeights()) {
    radius_px_ = 0;
    return false;
  }
  int max_width_px = 0;
  for (const cv::Size& s : sizes) max_width_px = std::max(max_width_px, s.width);
  sums_.assign(static_cast<std::size_t>(max_width_px + 2 * radius_px_), 0);
  for (const cv::Size& s : sizes) {
    if (!reproduces(s)) {
      radius_px_ = 0;
      return false;
    }
  }
  return true;
}

// A vertical line of 255 in a flat image: every column sum is 255 * 256, so the output next to the line
// is (255 * 256 * w + 2^15) >> 16 = floor(w + (128 - w) / 256) = w for 0 <= w <= 128.
bool FixedPointGaussian::readWeights() {
  constexpr int kSide = 4 * kMaxRadiusPx + 3;
  constexpr int kLine = kSide / 2;
  cv::Mat line(kSide, kSide, CV_8UC1, cv::Scalar(0));
  line.col(kLine).setTo(255);
  cv::Mat out;
  cv::GaussianBlur(line, out, kernel_, sigma_px_);
  const std::uint8_t* row = out.ptr<std::uint8_t>(kLine);
  if (row[kLine - kMaxRadiusPx - 1] != 0) return false;  // wider than kMaxRadiusPx
  int sum = row[kLine];
  weight_.fill(0);
  weight_[0] = row[kLine];
  for (int k = 1; k <= kMaxRadiusPx; ++k) {
    if (row[kLine - k] != row[kLine + k]) return false;  // not symmetric: not the kernel assumed here
    weight_[k] = row[kLine + k];
    sum += 2 * weight_[k];
    if (weight_[k] != 0) radius_px_ = k;
  }
  return sum == kWeightSum && weight_[0] <= 128 && radius_px_ >= 1;
}

// Random texture and a saturated image of this size, through both blurs.
bool FixedPointGaussian::reproduces(cv::Size size) {
  if (size.width <= 2 * radius_px_ || size.height <= 2 * radius_px_) return false;
  cv::Mat image(size, CV_8UC1);
  cv::RNG rng(0x5eed);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::Mat expected, got;
  for (int trial = 0; trial < 2; ++trial) {
    if (trial == 1) image.setTo(255);
    cv::GaussianBlur(image, expected, kernel_, sigma_px_);
    apply(image, &got);
    if (cv::norm(expected, got, cv::NORM_INF) != 0.0) return false;
  }
  return true;
}

void FixedPointGaussian::apply(const cv::Mat& src, cv::Mat* dst) {
  dst->create(src.size(), CV_8UC1);
  kBlurByRadius[radius_px_](weight_, src, dst, sums_.data() + radius_px_);
}

}  // namespace deepnav
