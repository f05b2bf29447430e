#include "vision/markers/marker_detector.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "base/fail.h"
#include "vision/markers/aruco_dictionary.h"

namespace deepnav {

bool validateMarkerDetectorConfig(const MarkerDetectorConfig& c, std::string* error) {
  int dictionary_id = 0;
  if (!arucoDictionaryFromName(c.dictionary, &dictionary_id)) {
    return fail(error, "dictionary: unknown ArUco dictionary '" + c.dictionary + "'");
  }
  if (!(c.marker_size_m > 0.0)) return fail(error, "marker_size_m: must be > 0");
  if (!(c.camera.fx_px > 0.0) || !(c.camera.fy_px > 0.0))
    return fail(error, "camera.fx_px/fy_px: must be > 0");
  if (!std::isfinite(c.camera.cx_px) || !std::isfinite(c.camera.cy_px)) {
    return fail(error, "camera.cx_px/cy_px: must be finite");
  }
  const CornerRefinementConfig& r = c.corner_refinement;
  if (!(r.window_cells > 0.0 && r.window_cells <= 1.0)) {
    return fail(error, "corner_refinement.window_cells: must be in (0, 1]");
  }
  if (r.max_half_window_px < 1 || r.max_half_window_px > 20) {
    return fail(error, "corner_refinement.max_half_window_px: must be in [1, 20]");
  }
  if (r.max_iterations < 1 || r.max_iterations > 1000) {
    return fail(error, "corner_refinement.max_iterations: must be in [1, 1000]");
  }
  if (!(r.min_accuracy_px > 0.0 && r.min_accuracy_px <= 1.0)) {
    return fail(error, "corner_refinement.min_accuracy_px: must be in (0, 1]");
  }
  if (!(c.ambiguity.corner_sigma_px > 0.0))
    return fail(error, "ambiguity.corner_sigma_px: must be > 0");
  if (!(c.ambiguity.ambiguity_chi2 >= 0.0))
    return fail(error, "ambiguity.ambiguity_chi2: must be >= 0");
  if (c.coarse.margin_px < 0 || c.coarse.margin_px > 200)
    return fail(error, "coarse.margin_px: must be in [0, 200]");
  if (!(c.coarse.margin_sides >= 0.0 && c.coarse.margin_sides <= 4.0))
    return fail(error, "coarse.margin_sides: must be in [0, 4]");
  if (c.coarse.threshold_window_max_px < 3 || c.coarse.threshold_window_max_px > 23)
    return fail(error, "coarse.threshold_window_max_px: must be in [3, 23]");
  if (c.coarse.track_margin_px < 0 || c.coarse.track_margin_px > 200)
    return fail(error, "coarse.track_margin_px: must be in [0, 200]");
  if (c.coarse.full_search_every_pairs < 1 || c.coarse.full_search_every_pairs > 1000)
    return fail(error, "coarse.full_search_every_pairs: must be in [1, 1000]");
  return true;
}

bool MarkerDetector::init(const MarkerDetectorConfig& config, std::string* error) {
  initialised_ = false;
  if (!validateMarkerDetectorConfig(config, error)) return false;
  config_ = config;
  int dictionary_id = 0;
  arucoDictionaryFromName(config.dictionary, &dictionary_id);
  dictionary_ = cv::aruco::getPredefinedDictionary(dictionary_id);
  params_ = cv::aruco::DetectorParameters::create();
  params_->cornerRefinementMethod =
      cv::aruco::CORNER_REFINE_NONE;  // refined per marker in detect()
  cells_across_ = dictionary_->markerSize + 2 * params_->markerBorderBits;
  region_params_ = cv::aruco::DetectorParameters::create();
  region_params_->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
  if (config.coarse_search) coarse_.init(dictionary_, config.coarse);
  tracked_.clear();
  untracked_pairs_ = 0;
  corners_.reserve(MarkerObservations::kCapacity * 2);
  ids_.reserve(MarkerObservations::kCapacity * 2);
  initialised_ = true;
  return true;
}

bool MarkerDetector::detect(const cv::Mat& grey_or_bgr, MarkerObservations* out) {
  out->clear();
  if (!initialised_ || grey_or_bgr.empty()) return false;
  const cv::Mat* grey = &grey_or_bgr;
  if (grey_or_bgr.type() == CV_8UC3) {
    cv::cvtColor(grey_or_bgr, grey_, cv::COLOR_BGR2GRAY);  // reuses grey_ once sized
    grey = &grey_;
  } else if (grey_or_bgr.type() != CV_8UC1) {
    return false;
  }
  corners_.clear();
  ids_.clear();
  if (config_.coarse_search) {
    detectCoarseToFine(*grey);
  } else {
    cv::aruco::detectMarkers(*grey, dictionary_, corners_, ids_, params_);
  }
  for (size_t i = 0; i < ids_.size(); ++i) {
    if (out->count == MarkerObservations::kCapacity) {
      ++out->dropped;
      continue;
    }
    if (corners_[i].size() != 4) {
      ++out->pose_failures;
      continue;
    }
    refineMarkerCorners(*grey, cells_across_, config_.corner_refinement, &corners_[i]);
    MarkerObservation& obs = out->items[out->count];
    obs = MarkerObservation{};
    obs.id = ids_[i];
    for (int k = 0; k < 4; ++k)
      obs.corners_px[k] = Eigen::Vector2d(corners_[i][k].x, corners_[i][k].y);
    if (!estimateSquareMarkerPose(obs.corners_px, config_.marker_size_m, config_.camera,
                                  config_.ambiguity, &obs)) {
      ++out->pose_failures;
      continue;
    }
    ++out->count;
  }
  return true;
}

// While markers are tracked: the coarse regions and the previous pair's markers. While none is: the
// coarse regions, and every full_search_every_pairs-th pair the whole image (a marker first seen far
// away is too small to be a quad at half resolution).
void MarkerDetector::detectCoarseToFine(const cv::Mat& grey) {
  if (tracked_.empty() && ++untracked_pairs_ >= config_.coarse.full_search_every_pairs) {
    untracked_pairs_ = 0;
    cv::aruco::detectMarkers(grey, dictionary_, corners_, ids_, params_);
  } else {
    detectInRegions(grey);
  }
  if (!corners_.empty()) untracked_pairs_ = 0;
  tracked_.assign(corners_.begin(), corners_.end());
}

// The whole-image detector's perimeter limits are fractions of the image's larger side (OpenCV 4.6
// truncates rate x side to whole px); in a rectangle they are set so that they come to the same px.
void MarkerDetector::detectInRegions(const cv::Mat& grey) {
  coarse_.find(grey, tracked_, &regions_);
  const double side_px = std::max(grey.cols, grey.rows);
  const double min_perimeter_px = std::floor(params_->minMarkerPerimeterRate * side_px) + 0.5;
  const double max_perimeter_px = std::floor(params_->maxMarkerPerimeterRate * side_px) + 0.5;
  for (const cv::Rect& r : regions_) {
    const double region_side_px = std::max(r.width, r.height);
    region_params_->minMarkerPerimeterRate = min_perimeter_px / region_side_px;
    region_params_->maxMarkerPerimeterRate = max_perimeter_px / region_side_px;
    region_corners_.clear();
    region_ids_.clear();
    cv::aruco::detectMarkers(grey(r), dictionary_, region_corners_, region_ids_, region_params_);
    for (std::size_t i = 0; i < region_ids_.size(); ++i) {
      for (cv::Point2f& p : region_corners_[i]) p += cv::Point2f(static_cast<float>(r.x), static_cast<float>(r.y));
      corners_.push_back(region_corners_[i]);
      ids_.push_back(region_ids_[i]);
    }
  }
}

}  // namespace deepnav
