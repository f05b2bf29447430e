#pragma once
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <yaml-cpp/yaml.h>

#include "vision/calib/stereo_calibration.h"

namespace deepnav {

// What an importer produced: the calibration, and remarks for the user (a conversion made, its error).
struct ImportedCalibration {
  StereoCalibration calibration;
  std::vector<std::string> notes;
};

// The checks every importer makes; each fails with one message "<file>: key '<key>' ..." naming where the
// value came from.
bool checkCameraMatrix(const cv::Matx33d& K, const std::string& file, const std::string& key, std::string* error);
// R^T R = I to 1e-4 (files print 6-9 digits) and det R = +1.
bool checkRotation(const cv::Matx33d& R, const std::string& file, const std::string& key, std::string* error);
bool checkBaseline(const cv::Vec3d& T, const std::string& file, const std::string& key, std::string* error);
bool checkSameResolution(cv::Size left, cv::Size right, const std::string& file, const std::string& key,
                         std::string* error);
// 4, 5, 8, 12 or 14 coefficients (OpenCV's models) and finite.
bool checkDistortion(const cv::Mat& dist, const std::string& file, const std::string& key, std::string* error);

// YAML (yaml-cpp) readers of the Kalibr and camera_info files: `key` under `parent` (both named in
// messages, dotted: "cam1.T_cn_cnm1").
bool readYamlNumbers(const YAML::Node& parent, const std::string& key, const std::string& file,
                     const std::string& prefix, std::size_t expected, std::vector<double>* out, std::string* error);
bool readYamlString(const YAML::Node& parent, const std::string& key, const std::string& file,
                    const std::string& prefix, std::string* out, std::string* error);
bool readYamlInt(const YAML::Node& parent, const std::string& key, const std::string& file, const std::string& prefix,
                 int* out, std::string* error);

}  // namespace deepnav
