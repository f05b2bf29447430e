#include "vision/markers/coarse_marker_regions.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace deepnav {

void CoarseMarkerRegions::init(const cv::Ptr<cv::aruco::Dictionary>& dictionary,
                               const CoarseRegionConfig& config) {
  config_ = config;
  dictionary_ = dictionary;
  params_ = cv::aruco::DetectorParameters::create();
  params_->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
  params_->adaptiveThreshWinSizeMax = config.threshold_window_max_px;
}

void CoarseMarkerRegions::find(const cv::Mat& grey, const std::vector<std::vector<cv::Point2f>>& tracked_px,
                               std::vector<cv::Rect>* regions) {
  regions->clear();
  cv::resize(grey, half_, cv::Size(), 0.5, 0.5, cv::INTER_AREA);
  quads_.clear();
  rejected_.clear();
  ids_.clear();
  cv::aruco::detectMarkers(half_, dictionary_, quads_, ids_, params_, rejected_);
  const cv::Rect image(0, 0, grey.cols, grey.rows);
  for (const auto& q : quads_) addQuad(q, 2.0f, 0, image, regions);
  for (const auto& q : rejected_) addQuad(q, 2.0f, 0, image, regions);
  for (const auto& q : tracked_px) addQuad(q, 1.0f, config_.track_margin_px, image, regions);
  mergeOverlappingRects(regions);
}

void CoarseMarkerRegions::addQuad(const std::vector<cv::Point2f>& quad_px, float scale, int extra_px,
                                  const cv::Rect& image, std::vector<cv::Rect>* regions) const {
  if (quad_px.size() != 4) return;
  const float shift_px = 0.5f * (scale - 1.0f);
  float x0 = 1e9f, y0 = 1e9f, x1 = -1e9f, y1 = -1e9f, longest_px = 0.0f;
  for (int k = 0; k < 4; ++k) {
    // Pixel centres at integer coordinates at both sizes: full = 2 half + 0.5 (scale 1: unchanged).
    const float x = scale * quad_px[k].x + shift_px, y = scale * quad_px[k].y + shift_px;
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x);
    y1 = std::max(y1, y);
    const cv::Point2f side = quad_px[k] - quad_px[(k + 1) % 4];
    longest_px = std::max(longest_px, scale * std::hypot(side.x, side.y));
  }
  const int m = std::max(config_.margin_px, static_cast<int>(config_.margin_sides * longest_px)) + extra_px;
  const int left = static_cast<int>(std::floor(x0)) - m, top = static_cast<int>(std::floor(y0)) - m;
  const int right = static_cast<int>(std::ceil(x1)) + m, bottom = static_cast<int>(std::ceil(y1)) + m;
  const cv::Rect r = cv::Rect(left, top, right - left + 1, bottom - top + 1) & image;
  if (r.area() > 0) regions->push_back(r);
}

void mergeOverlappingRects(std::vector<cv::Rect>* rects) {
  bool merged = true;
  while (merged) {
    merged = false;
    for (std::size_t i = 0; i < rects->size() && !merged; ++i) {
      for (std::size_t j = i + 1; j < rects->size(); ++j) {
        if (((*rects)[i] & (*rects)[j]).area() == 0) continue;
        (*rects)[i] |= (*rects)[j];
        rects->erase(rects->begin() + static_cast<std::ptrdiff_t>(j));
        merged = true;
        break;
      }
    }
  }
}

}  // namespace deepnav
