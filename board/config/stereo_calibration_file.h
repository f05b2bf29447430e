#pragma once
#include <string>

#include "vision/calib/stereo_calibration.h"

namespace deepnav {

// What a calibration file holds besides the calibration (for the record; not needed to rectify).
struct StereoCalibrationInfo {
  double rms_px = 0.0;
  int pairs_used = 0;
  std::string target;  // one-line description of the ChArUco target
};

// Writes the stereo calibration as OpenCV YAML (cv::FileStorage): image_width, image_height,
// camera_matrix_left/right (3x3), distortion_coefficients_left/right (1xN, k1 k2 p1 p2 [k3...]),
// R (3x3) and T (3x1, metres) with p_in_right = R p_in_left + T, and the info fields.
bool writeStereoCalibrationFile(const std::string& path, const StereoCalibration& calibration,
                                const StereoCalibrationInfo& info, std::string* error);

// Reads it back; a missing or malformed field fails with "<path>: field '<name>' ...".
bool readStereoCalibrationFile(const std::string& path, StereoCalibration* calibration, std::string* error);

// The same file's text (for a recording's metadata, or a calibration made up by the simulator).
std::string stereoCalibrationText(const StereoCalibration& calibration, const StereoCalibrationInfo& info);
// Parses such a text (the content of a calibration file); errors name `name` and the field.
bool parseStereoCalibrationText(const std::string& text, const std::string& name, StereoCalibration* calibration,
                                std::string* error);

}  // namespace deepnav
