#pragma once
#include <opencv2/aruco.hpp>
#include <opencv2/core.hpp>
#include <vector>

namespace deepnav {

// Where a marker can be, from a search on the image at half resolution (the optional coarse-to-fine
// mode of MarkerDetector, vision.markers_coarse_search).
//
// On a dive frame most of cv::aruco::detectMarkers' time goes to tracing the contours of the texture
// and noise in three adaptive thresholds of the whole image (68 % in findContours). At half
// resolution that costs a quarter. Every quad found there, decoded or not (the rejected candidates:
// a marker whose cells are too small to decode at half size is still a quad), becomes a full-
// resolution rectangle: the quad's box doubled, plus a margin of max(margin_px, margin_sides x its
// longest side) (the adaptive threshold's largest window is 23 px, so the detector sees the same
// pixels around the marker as on the whole image). Overlapping rectangles are merged, so that each
// marker lies in one of them; the caller runs the full-resolution detector inside each.
struct CoarseRegionConfig {
  int margin_px = 16;           // smallest margin around a quad, full-resolution px
  double margin_sides = 0.25;   // margin as a fraction of the quad's longest side
  int threshold_window_max_px = 13;  // adaptive threshold windows 3..this at half resolution
  // The previous pair's markers are searched again at full resolution (a far marker too small to be a
  // quad at half resolution stays found once seen): their box plus the margin above plus this much for
  // the image motion between two pairs (full-resolution px).
  int track_margin_px = 24;
  // While no marker is tracked, every this many pairs the whole image is searched at full resolution, so
  // a marker that first appears far away (too small at half resolution) is found within this many pairs.
  int full_search_every_pairs = 5;
};

class CoarseMarkerRegions {
 public:
  void init(const cv::Ptr<cv::aruco::Dictionary>& dictionary, const CoarseRegionConfig& config);

  // grey: CV_8UC1. Fills *regions (cleared first) with disjoint rectangles inside the image: around the
  // quads found at half resolution and around tracked_px, the previous pair's markers (full-resolution
  // corners).
  void find(const cv::Mat& grey, const std::vector<std::vector<cv::Point2f>>& tracked_px,
            std::vector<cv::Rect>* regions);

 private:
  // A quad's box in full-resolution px (corners scaled by `scale`, pixel centres aligned), grown by
  // max(margin_px, margin_sides x its longest side) + extra_px.
  void addQuad(const std::vector<cv::Point2f>& quad_px, float scale, int extra_px, const cv::Rect& image,
               std::vector<cv::Rect>* regions) const;

  CoarseRegionConfig config_;
  cv::Ptr<cv::aruco::Dictionary> dictionary_;
  cv::Ptr<cv::aruco::DetectorParameters> params_;
  cv::Mat half_;
  std::vector<std::vector<cv::Point2f>> quads_, rejected_;
  std::vector<int> ids_;
};

// Merges overlapping rectangles in place until none overlap (order: first-found first).
void mergeOverlappingRects(std::vector<cv::Rect>* rects);

}  // namespace deepnav
