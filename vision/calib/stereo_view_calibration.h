#pragma once
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/calib/stereo_calibration.h"
#include "vision/calib/target_view.h"

namespace deepnav {

// One stereo pair of calibration images (grey, same size).
struct CalibrationPairInput {
  std::string name;  // for the report (file name, frame number)
  cv::Mat left;
  cv::Mat right;
};

// What happened to one pair.
struct CalibrationPairReport {
  std::string name;
  bool used = false;
  std::string reason;  // why it was rejected (empty when used)
  int corners_left = 0;
  int corners_right = 0;
  int corners_common = 0;  // seen by both cameras (used for the extrinsics)
  double edge_width_left_px = 0.0;
  double edge_width_right_px = 0.0;
  double rms_left_px = 0.0;  // reprojection error of this view after the stereo calibration
  double rms_right_px = 0.0;
};

struct StereoCalibrationResult {
  StereoCalibration calibration;
  double rms_px = 0.0;            // stereoCalibrate's overall reprojection error (both cameras)
  double rms_left_mono_px = 0.0;  // cv::calibrateCamera of each camera alone
  double rms_right_mono_px = 0.0;
  int pairs_used = 0;
  std::vector<CalibrationPairReport> pairs;
};

// The acceptance thresholds of the views, whatever the target.
struct ViewScreening {
  int min_corners = 12;            // corners a view needs in each camera
  double max_edge_width_px = 3.5;  // views whose edges are wider (blur) are rejected
  double duplicate_px = 4.0;       // views whose corners moved less than this from a kept view are duplicates
  bool fix_k3 = true;              // estimate k1 k2 p1 p2 only
  bool whole_board = false;        // min_corners is the whole board (a view has all or none): says so
};

// Finds the target in one grey image (an empty view when it is not there).
using ViewDetector = std::function<TargetView(const cv::Mat& grey)>;
// A target-specific step on the two views of one pair (e.g. numbering the right view's corners as the left
// view's); returns why the pair is rejected, or "".
using PairCheck = std::function<std::string(const TargetView& left, TargetView* right)>;

// Detects the target in every pair, screens the pairs (too few corners, blur, duplicate view, pair_check),
// calibrates each camera with cv::calibrateCamera, then both together with cv::stereoCalibrate on the
// corners both cameras see (intrinsics refined from the mono estimates). board_corners_m[id] is the corner
// of that id in the board's frame (metres, z = 0). False with a message when fewer than 4 pairs remain or
// the optimisation fails; the per-pair reports are filled either way.
bool calibrateStereoViews(const std::vector<CalibrationPairInput>& pairs, const ViewDetector& detect,
                          const std::vector<cv::Point3f>& board_corners_m, const ViewScreening& screening,
                          const PairCheck& pair_check, StereoCalibrationResult* result, std::string* error);

}  // namespace deepnav
