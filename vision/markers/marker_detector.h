#pragma once
#include <opencv2/aruco.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "base/marker_observation.h"
#include "vision/markers/coarse_marker_regions.h"
#include "vision/markers/marker_corner_refinement.h"
#include "vision/markers/pinhole_intrinsics.h"
#include "vision/markers/square_marker_pose.h"

namespace deepnav {

// Every parameter of the marker detector, with its unit and default (declared here only).
struct MarkerDetectorConfig {
  std::string dictionary = "DICT_4X4_50";  // OpenCV predefined ArUco dictionary name
  double marker_size_m = 0.15;             // black border side length, > 0
  PinholeIntrinsics camera;                // rectified image, no distortion; fx, fy > 0
  CornerRefinementConfig
      corner_refinement;            // subpixel corners, always on (window sized to the cells)
  MarkerAmbiguityConfig ambiguity;  // when both IPPE solutions are flagged ambiguous
  // Coarse-to-fine search (off: the whole image at full resolution, as always): quads found at half
  // resolution, then the full-resolution detector only in rectangles around them
  // (coarse_marker_regions.h). The markers it finds have the same corners as the whole-image search;
  // it misses some that only the full resolution shows as quads (small and far). Board key
  // vision.markers_coarse_search.
  bool coarse_search = false;
  CoarseRegionConfig coarse;
};

// False with a message naming the key when a field is out of range or the dictionary unknown.
bool validateMarkerDetectorConfig(const MarkerDetectorConfig& config, std::string* error);

// ArUco markers and their poses in one rectified image (OpenCV 4.6 contrib API):
// cv::aruco::detectMarkers finds and decodes the quads, each marker's corners are refined to
// subpixel with a window sized to its cells (marker_corner_refinement.h: OpenCV 4.6's
// CORNER_REFINE_SUBPIX uses one fixed window for every size, which spoils small or oblique
// markers), then one IPPE_SQUARE pose per marker (square_marker_pose.h). Allocation: the output is
// fixed-capacity and the detector's buffers are reused, but OpenCV's detectMarkers and
// solvePnPGeneric allocate internally on every call (outside our control).
class MarkerDetector {
 public:
  bool init(const MarkerDetectorConfig& config, std::string* error);

  // image: CV_8UC1 or CV_8UC3 (BGR). Fills *out (cleared first) in detection order; markers beyond
  // MarkerObservations::kCapacity are counted in out->dropped. False when not initialised or the
  // image is empty or of another type (then *out is cleared).
  bool detect(const cv::Mat& grey_or_bgr, MarkerObservations* out);

  bool initialised() const { return initialised_; }
  const MarkerDetectorConfig& config() const { return config_; }

 private:
  void detectCoarseToFine(const cv::Mat& grey);
  void detectInRegions(const cv::Mat& grey);

  MarkerDetectorConfig config_;
  cv::Ptr<cv::aruco::Dictionary> dictionary_;
  cv::Ptr<cv::aruco::DetectorParameters> params_;
  cv::Ptr<cv::aruco::DetectorParameters> region_params_;  // coarse_search: in one rectangle
  CoarseMarkerRegions coarse_;
  std::vector<cv::Rect> regions_;
  std::vector<std::vector<cv::Point2f>> region_corners_;
  std::vector<int> region_ids_;
  std::vector<std::vector<cv::Point2f>> tracked_;  // coarse_search: the previous pair's markers (full px)
  int untracked_pairs_ = 0;                         // coarse_search: pairs since the last full search
  int cells_across_ = 6;  // bits of the dictionary + 2 border cells
  cv::Mat grey_;
  std::vector<std::vector<cv::Point2f>> corners_;
  std::vector<int> ids_;
  bool initialised_ = false;
};

}  // namespace deepnav
