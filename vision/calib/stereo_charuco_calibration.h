#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "vision/calib/charuco_target.h"
#include "vision/calib/charuco_view.h"
#include "vision/calib/stereo_calibration.h"

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
  std::string reason;          // why it was rejected (empty when used)
  int corners_left = 0;
  int corners_right = 0;
  int corners_common = 0;      // seen by both cameras (used for the extrinsics)
  double edge_width_left_px = 0.0;
  double edge_width_right_px = 0.0;
  double rms_left_px = 0.0;    // reprojection error of this view after the stereo calibration
  double rms_right_px = 0.0;
};

struct StereoCharucoResult {
  StereoCalibration calibration;
  double rms_px = 0.0;          // stereoCalibrate's overall reprojection error (both cameras)
  double rms_left_mono_px = 0.0;   // calibrateCameraCharuco of each camera alone
  double rms_right_mono_px = 0.0;
  int pairs_used = 0;
  std::vector<CalibrationPairReport> pairs;
};

// Screens the pairs (too few corners, blur, duplicate view), calibrates each camera with
// calibrateCameraCharuco, then both together with cv::stereoCalibrate on the corners both cameras see
// (intrinsics refined from the mono estimates). False with a message when fewer than 4 pairs remain or
// the optimisation fails; the per-pair reports are filled either way.
bool calibrateStereoCharuco(const std::vector<CalibrationPairInput>& pairs, const CharucoTarget& target,
                            StereoCharucoResult* result, std::string* error);

}  // namespace deepnav
