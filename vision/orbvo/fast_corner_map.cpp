#include "vision/orbvo/fast_corner_map.h"

#include <algorithm>
#include <array>
#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

namespace deepnav {
namespace {

constexpr int kCircle = 16;
constexpr int kCheckWidthPx = 97;   // the size of the images reproducesOpenCv() uses
constexpr int kCheckHeightPx = 83;

// The Bresenham circle of radius 3 as (dx, dy), in order around it (OpenCV's order: any rotation or
// direction of it gives the same arcs).
constexpr std::array<std::array<int, 2>, kCircle> kCircleOffsets = {{{0, 3}, {1, 3}, {2, 2}, {3, 1},
                                                                     {3, 0}, {3, -1}, {2, -2}, {1, -3},
                                                                     {0, -3}, {-1, -3}, {-2, -2}, {-3, -1},
                                                                     {-3, 0}, {-3, 1}, {-2, 2}, {-1, 3}}};

// Over the 16 arcs of 9 circle values: the largest arc minimum (Worst = min, Best = max) or the smallest
// arc maximum (Worst = max, Best = min). An arc from an even k is (k..k+7) and k+8, one from an odd k is k
// and (k+1..k+8): only the 8 runs of 8 from even k are needed, from runs of 2 and 4 from even k, so
// 8 + 8 + 8 + 16 + 15 = 55 operations per call. V: int (scalar) or 16 u8 lanes.
template <typename V, typename Worst, typename Best>
inline V bestArc(const std::array<V, kCircle>& c, Worst worst, Best best) {
  constexpr int kHalf = kCircle / 2;
  std::array<V, kHalf> w2, w4, w8;  // w*[i]: the run of * values from 2i
#pragma GCC unroll 8
  for (int i = 0; i < kHalf; ++i) w2[i] = worst(c[2 * i], c[2 * i + 1]);
#pragma GCC unroll 8
  for (int i = 0; i < kHalf; ++i) w4[i] = worst(w2[i], w2[(i + 1) % kHalf]);
#pragma GCC unroll 8
  for (int i = 0; i < kHalf; ++i) w8[i] = worst(w4[i], w4[(i + 2) % kHalf]);
  V result = worst(w8[0], c[8]);
#pragma GCC unroll 8
  for (int i = 0; i < kHalf; ++i) {
    if (i > 0) result = best(result, worst(w8[i], c[(2 * i + 8) % kCircle]));
    result = best(result, worst(c[2 * i + 1], w8[(i + 1) % kHalf]));
  }
  return result;
}

// The strength of one pixel (the vector code's formulation, below, in plain ints).
std::uint8_t strengthAt(const std::array<const std::uint8_t*, kCircle>& circle, const std::uint8_t* centre,
                        int x) {
  std::array<int, kCircle> c;
  for (int k = 0; k < kCircle; ++k) c[k] = circle[k][x];
  const auto vmin = [](int a, int b) { return std::min(a, b); };
  const auto vmax = [](int a, int b) { return std::max(a, b); };
  const int p = centre[x];
  const int brighter = bestArc(c, vmin, vmax) - p;
  const int darker = p - bestArc(c, vmax, vmin);
  return static_cast<std::uint8_t>(std::max({brighter, darker, 0}));
}

#if CV_SIMD128
using V = cv::v_uint8x16;

// 16 pixels from x on. Saturating u8 subtraction of the centre is monotone, so the brighter strength
// max_arc min_j (c_j - p)+ equals (max_arc min_j c_j - p)+, the darker one (p - min_arc max_j c_j)+:
// the arcs run on the raw circle values, once for each direction. A pixel whose circle has no two
// neighbouring compass points (0, 4, 8, 12) both brighter or both darker by more than `floor` cannot
// be a corner above it (every arc of 9 holds two of them): when no lane can, the block is left at 0
// without the arcs, as FAST's own first test does.
void strength16(const std::array<const std::uint8_t*, kCircle>& circle, const std::uint8_t* centre,
                int x, const V& floor, std::uint8_t* out) {
  const V p = cv::v_load(centre + x);
  std::array<V, kCircle> c;
#pragma GCC unroll 16
  for (int k = 0; k < kCircle; ++k) c[k] = cv::v_load(circle[k] + x);
  const auto brighter = [&](int k) { return (c[k] - p) > floor; };
  const auto darker = [&](int k) { return (p - c[k]) > floor; };
  const V candidate = ((brighter(0) | brighter(8)) & (brighter(4) | brighter(12))) |
                      ((darker(0) | darker(8)) & (darker(4) | darker(12)));
  if (!cv::v_check_any(candidate)) {
    cv::v_store(out + x, cv::v_setzero_u8());
    return;
  }
  const auto vmin = [](V a, V b) { return cv::v_min(a, b); };
  const auto vmax = [](V a, V b) { return cv::v_max(a, b); };
  const V brightest_arc = bestArc(c, vmin, vmax);  // max over arcs of the arc's minimum
  const V darkest_arc = bestArc(c, vmax, vmin);    // min over arcs of the arc's maximum
  cv::v_store(out + x, cv::v_max(brightest_arc - p, p - darkest_arc));
}
#endif

// s of row y's pixels x_begin <= x < x_end (at least kRadiusPx from the image's edges) in blocks of 16 from
// x_begin, the last one moved back to end at x_end (its recomputed pixels get the same values); block b
// skips the pixels that cannot be corners above block_floor[b]. Fewer than 16 pixels: every strength, exactly.
void strengthRow(const cv::Mat& image, int y, int x_begin, int x_end, const std::uint8_t* block_floor,
                 std::uint8_t* out) {
  std::array<const std::uint8_t*, kCircle> circle{};
  for (int k = 0; k < kCircle; ++k) {
    circle[k] = image.ptr<std::uint8_t>(y + kCircleOffsets[k][1]) + kCircleOffsets[k][0];
  }
  const std::uint8_t* centre = image.ptr<std::uint8_t>(y);
  int x = x_begin;
#if CV_SIMD128
  constexpr int kLanes = FastCornerMap::kBlockPx;
  if (x_end - x_begin >= kLanes) {
    for (int b = 0; x < x_end; ++b, x += kLanes) {
      strength16(circle, centre, std::min(x, x_end - kLanes), cv::v_setall_u8(block_floor[b]), out);
    }
  }
#endif
  (void)block_floor;  // the scalar path computes every strength exactly
  for (; x < x_end; ++x) out[x] = strengthAt(circle, centre, x);
}

// cv::FAST's non-maximum test inside the cell: s beats every 8-neighbour in the cell.
bool isCellMaximum(const cv::Mat& strength, const cv::Rect& cell, int x, int y) {
  const std::uint8_t* row = strength.ptr<std::uint8_t>(y) + x;
  const std::uint8_t s = *row;
  const std::size_t step = strength.step;
  if (x > cell.x && x + 1 < cell.x + cell.width && y > cell.y && y + 1 < cell.y + cell.height) {
    const std::uint8_t* up = row - step;
    const std::uint8_t* down = row + step;
    return s > row[-1] && s > row[1] && s > up[-1] && s > up[0] && s > up[1] && s > down[-1] &&
           s > down[0] && s > down[1];
  }
  const int x0 = std::max(x - 1, cell.x);
  const int x1 = std::min(x + 1, cell.x + cell.width - 1);
  const int y0 = std::max(y - 1, cell.y);
  const int y1 = std::min(y + 1, cell.y + cell.height - 1);
  for (int v = y0; v <= y1; ++v) {
    const std::uint8_t* r = strength.ptr<std::uint8_t>(v);
    for (int u = x0; u <= x1; ++u) {
      if ((u != x || v != y) && r[u] >= s) return false;
    }
  }
  return true;
}

}  // namespace

void FastCornerMap::init(int max_width_px, int max_height_px) {
  constexpr int kCheckArea = kCheckWidthPx * kCheckHeightPx;
  const std::size_t area = static_cast<std::size_t>(std::max(max_width_px, 0)) * std::max(max_height_px, 0);
  buffer_.assign(std::max<std::size_t>(area, kCheckArea), 0);
  block_floor_.assign(static_cast<std::size_t>(std::max(max_width_px, kCheckWidthPx)) / kBlockPx + 1, 0);
  exact_ = reproducesOpenCv();
}

bool FastCornerMap::prepare(const cv::Mat& image, int x_begin, int x_end, int y_begin, int y_end) {
  CV_Assert(image.type() == CV_8UC1 &&
            static_cast<std::size_t>(image.rows) * image.cols <= buffer_.size());
  CV_Assert(x_begin >= kRadiusPx && y_begin >= kRadiusPx && x_end <= image.cols - kRadiusPx &&
            y_end <= image.rows - kRadiusPx);
  // an image as large as the init size but wider would need more blocks per row than init() sized
  CV_Assert(static_cast<std::size_t>(x_end - x_begin + kBlockPx - 1) / kBlockPx <= block_floor_.size());
  if (strength_.data != buffer_.data() || strength_.size() != image.size()) {
    strength_ = cv::Mat(image.rows, image.cols, CV_8UC1, buffer_.data());
  }
  return x_begin < x_end && y_begin < y_end;
}

void FastCornerMap::computeRows(const cv::Mat& image, int x_begin, int x_end, int y_begin, int y_end) {
  for (int y = y_begin; y < y_end; ++y) {
    strengthRow(image, y, x_begin, x_end, block_floor_.data(), strength_.ptr<std::uint8_t>(y));
  }
}

void FastCornerMap::compute(const cv::Mat& image, const cv::Rect& area, int floor_threshold) {
  if (!prepare(image, area.x, area.x + area.width, area.y, area.y + area.height)) return;
  const int blocks = (area.width + kBlockPx - 1) / kBlockPx;
  std::fill(block_floor_.begin(), block_floor_.begin() + blocks, static_cast<std::uint8_t>(floor_threshold));
  computeRows(image, area.x, area.x + area.width, area.y, area.y + area.height);
}

void FastCornerMap::computeCells(const cv::Mat& image, int y_begin, int y_end, const int* x_edges,
                                 const int* floor_thresholds, int cells) {
  const int x_begin = x_edges[0];
  const int x_end = x_edges[cells];
  if (!prepare(image, x_begin, x_end, y_begin, y_end)) return;
  const int blocks = (x_end - x_begin + kBlockPx - 1) / kBlockPx;
  int cell = 0;
  for (int b = 0; b < blocks; ++b) {
    const int block_begin = std::min(x_begin + b * kBlockPx, x_end - kBlockPx);
    const int block_end = block_begin + kBlockPx;
    while (x_edges[cell + 1] <= block_begin) ++cell;
    int floor = floor_thresholds[cell];
    for (int c = cell + 1; c < cells && x_edges[c] < block_end; ++c) floor = std::min(floor, floor_thresholds[c]);
    block_floor_[b] = static_cast<std::uint8_t>(floor);
  }
  computeRows(image, x_begin, x_end, y_begin, y_end);
}

void FastCornerMap::detect(const cv::Rect& cell, int threshold,
                           std::vector<cv::KeyPoint>* corners) const {
  corners->clear();
  const int x_end = cell.x + cell.width;
  const auto consider = [&](int x, int y, const std::uint8_t* row) {
    if (row[x] > threshold && isCellMaximum(strength_, cell, x, y)) {
      corners->emplace_back(static_cast<float>(x), static_cast<float>(y), 7.0f, -1.0f,
                            static_cast<float>(row[x] - 1));
    }
  };
  for (int y = cell.y; y < cell.y + cell.height; ++y) {
    const std::uint8_t* row = strength_.ptr<std::uint8_t>(y);
    int x = cell.x;
#if CV_SIMD128
    // most pixels are below the threshold: only the lanes above it are looked at, in order
    const cv::v_uint8x16 t = cv::v_setall_u8(static_cast<std::uint8_t>(threshold));
    for (; x + 16 <= x_end; x += 16) {
      for (int above = cv::v_signmask(cv::v_load(row + x) > t); above != 0; above &= above - 1) {
        consider(x + __builtin_ctz(static_cast<unsigned>(above)), y, row);
      }
    }
#endif
    for (; x < x_end; ++x) consider(x, y, row);
  }
}

namespace {

// Test images with many corners, ties of strength between neighbours and steps near the thresholds.
std::vector<cv::Mat> checkImages(int width_px, int height_px) {
  cv::RNG rng(0xfa57);
  cv::Mat noise(height_px, width_px, CV_8UC1);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::Mat smooth;
  cv::GaussianBlur(noise, smooth, cv::Size(0, 0), 1.2);
  cv::Mat blocks(height_px / 4 + 1, width_px / 4 + 1, CV_8UC1), blocky;
  rng.fill(blocks, cv::RNG::UNIFORM, 0, 4);
  cv::resize(blocks * 60, blocky, noise.size(), 0.0, 0.0, cv::INTER_NEAREST);
  cv::Mat faint(height_px, width_px, CV_8UC1);
  rng.fill(faint, cv::RNG::UNIFORM, 100, 112);
  return {noise, smooth, blocky, faint};
}

}  // namespace

bool FastCornerMap::sameCornersAsOpenCv(const cv::Mat& image, const cv::Rect& cell, int threshold,
                                        std::vector<cv::KeyPoint>* scratch) const {
  const cv::Rect roi(cell.x - kRadiusPx, cell.y - kRadiusPx, cell.width + 2 * kRadiusPx,
                     cell.height + 2 * kRadiusPx);
  std::vector<cv::KeyPoint> expected;
  cv::FAST(image(roi), expected, threshold, true, cv::FastFeatureDetector::TYPE_9_16);
  detect(cell, threshold, scratch);
  if (expected.size() != scratch->size()) return false;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const cv::KeyPoint& e = expected[i];
    const cv::KeyPoint& g = (*scratch)[i];
    if (e.pt.x + roi.x != g.pt.x || e.pt.y + roi.y != g.pt.y || e.response != g.response) return false;
  }
  return true;
}

// The check images cut into cells of uneven sizes (one at the 3 px margin), computed at two floors and
// detected at every threshold from the floor up, against cv::FAST on each widened cell.
bool FastCornerMap::reproducesOpenCv() {
  constexpr int kW = kCheckWidthPx, kH = kCheckHeightPx;
  const std::array<int, 5> thresholds = {1, 5, 9, 20, 40};
  const std::array<int, 4> xs = {kRadiusPx, 20, 51, kW - kRadiusPx};
  const std::array<int, 4> ys = {kRadiusPx, 31, 44, kH - kRadiusPx};
  std::vector<cv::KeyPoint> scratch;
  for (const cv::Mat& image : checkImages(kW, kH)) {
    for (int floor : {1, 9}) {
      compute(image, cv::Rect(kRadiusPx, kRadiusPx, kW - 2 * kRadiusPx, kH - 2 * kRadiusPx), floor);
      for (int gy = 0; gy + 1 < static_cast<int>(ys.size()); ++gy) {
        for (int gx = 0; gx + 1 < static_cast<int>(xs.size()); ++gx) {
          const cv::Rect cell(xs[gx], ys[gy], xs[gx + 1] - xs[gx], ys[gy + 1] - ys[gy]);
          for (int t : thresholds) {
            if (t >= floor && !sameCornersAsOpenCv(image, cell, t, &scratch)) return false;
          }
        }
      }
    }
  }
  return true;
}

}  // namespace deepnav
