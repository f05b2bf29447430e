#pragma once
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// FAST-9 corners of image cells, the same corners as cv::FAST(image(cell widened by 3 px), threshold,
// nonmax_suppression = true, TYPE_9_16) (Rosten & Drummond, "Machine learning for high-speed corner
// detection", ECCV 2006), with every step in 8-bit vector lanes (universal intrinsics: NEON on the
// vehicle). cv::FAST was 30 % of the ORB VO's instructions per pair; its candidates' scores are scalar.
//
// Why a strength map gives cv::FAST's corners: let s(p) be the corner strength, the largest over the 16
// arcs of 9 contiguous circle pixels of the smallest brightness step along the arc, all brighter or all
// darker than p (saturated at 0). p is a FAST corner at threshold t iff s(p) > t, and OpenCV's score
// (cornerScore) of a corner is s(p) - 1, whatever t. Its non-maximum suppression keeps a corner when its
// score beats the score of each of its 8 neighbours that is a corner (0 otherwise) and detected in the
// same call. A neighbour q that is not a corner has s(q) <= t < s(p), so the test is s(p) > s(q) for
// every 8-neighbour q inside the cell, and any value <= t for q changes nothing. Saturating u8
// subtraction is monotone, so the brighter strength is (max over arcs of the arc's minimum - p)+ and
// the darker one (p - min over arcs of the arc's maximum)+: 110 min/max per 16 pixels. init() checks the
// corners against cv::FAST on test images; when this OpenCV differs (another version, a HAL such as
// Carotene on ARM), exact() is false and the caller keeps cv::FAST.
class FastCornerMap {
 public:
  static constexpr int kRadiusPx = 3;  // of the Bresenham circle of 16 pixels
  static constexpr int kBlockPx = 16;  // pixels per vector block

  // Sizes the map for images up to this size and checks the result against cv::FAST. Allocates.
  void init(int max_width_px, int max_height_px);
  bool exact() const { return exact_; }

  // s(p) of the pixels in `area` of `image` (CV_8UC1 within the init size; `area` at least kRadiusPx
  // from its edges) that can be corners above `floor_threshold`; every other pixel of `area` gets a
  // value <= floor_threshold (0 mostly: 16 pixels that all fail FAST's compass-point test are
  // skipped), which detect() at thresholds >= floor_threshold cannot tell from its strength. Pixels
  // outside `area` keep what they had.
  void compute(const cv::Mat& image, const cv::Rect& area, int floor_threshold);

  // compute() of a row of cells side by side, [x_edges[i], x_edges[i + 1]) x [y_begin, y_end) with
  // floor_thresholds[i], i < cells (x_edges increasing): the blocks of 16 pixels run across the cells'
  // edges, each skipping only what cannot be a corner above the lowest floor of the cells it touches, so
  // detect() sees in each cell what compute() of that cell would give it, without a partly wasted block
  // at the end of every cell and row.
  void computeCells(const cv::Mat& image, int y_begin, int y_end, const int* x_edges,
                    const int* floor_thresholds, int cells);

  // The corners of `cell` (inside the computed area) at `threshold` (floor_threshold..255), in raster order as cv::FAST gives them: pt in image pixels, response the
  // score s - 1, size 7. Clears `corners` first; allocates only past its capacity.
  void detect(const cv::Rect& cell, int threshold, std::vector<cv::KeyPoint>* corners) const;

  // The strength map of the image of the last compute(), for tests.
  const cv::Mat& strength() const { return strength_; }

 private:
  bool prepare(const cv::Mat& image, int x_begin, int x_end, int y_begin, int y_end);
  void computeRows(const cv::Mat& image, int x_begin, int x_end, int y_begin, int y_end);
  bool reproducesOpenCv();
  bool sameCornersAsOpenCv(const cv::Mat& image, const cv::Rect& cell, int threshold,
                           std::vector<cv::KeyPoint>* scratch) const;

  std::vector<std::uint8_t> buffer_;
  std::vector<std::uint8_t> block_floor_;  // floor of each 16-pixel block of the rows being computed
  cv::Mat strength_;  // CV_8UC1 header on buffer_, the size of the last image
  bool exact_ = false;
};

}  // namespace deepnav
